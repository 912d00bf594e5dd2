// `meshparticles correspond INPUTS... --out DIR -n N`: particles that
// correspond across a population (correspondence/correspond_runner), each
// shape's evenness, and the shape model of the result
// (docs/CORRESPONDENCE.md).
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "cli/commands.hpp"
#include "correspondence/correspond_runner.hpp"
#include "options/number_options.hpp"

namespace meshparticles {

namespace {

struct CorrespondOptions {
  CorrespondRequest request;
  std::string out;
  bool no_scale = false;
  bool no_packing = false;
  std::string deformation = "graph";
};

void run_correspond_command(const CorrespondOptions& options) {
  CorrespondRequest request = options.request;
  request.out = options.out;
  request.scale = !options.no_scale;
  request.refinement.pack = !options.no_packing;
  request.deformation =
      options.deformation == deformation_name(TemplateDeformation::graph) ? TemplateDeformation::graph : TemplateDeformation::smooth;
  const std::optional<CorrespondOutcome> outcome = run_correspond(request);
  if (!outcome) return;
  std::printf("shapes      %zu, %zu particles each, template %s\n", outcome->meshes.size(), request.particles,
              outcome->meshes.front().c_str());
  std::printf("alignment   worst fit %.4f (rms distance at unit area)\n", outcome->worst_fit);
  std::printf("model       %lld modes; variance held by 1, 3, 5 modes:", static_cast<long long>(outcome->modes));
  for (const std::size_t m : {1, 3, 5}) {
    if (m <= outcome->compactness.size()) std::printf(" %.1f%%", 100 * outcome->compactness[m - 1]);
  }
  std::printf("\noutput      %s/{shapes/, model/, summary.json}\n", options.out.c_str());
}

}  // namespace

void add_correspond_command(CLI::App& app) {
  auto options = std::make_shared<CorrespondOptions>();
  CLI::App* command = app.add_subcommand(
      "correspond", "Particles at the same places on every shape of a population, and their shape model");
  command->add_option("inputs", options->request.inputs, "Mesh files, folders of meshes, .txt files listing meshes; the first is the template")
      ->required();
  command
      ->add_option("--out", options->out,
                   "Output directory: shapes/, model/, summary.json (and checkpoint/ while it runs: the same "
                   "command run again after a kill goes on from there)")
      ->required();
  add_whole_number_option(*command, "-n,--particles", options->request.particles, kParticleRange,
                          "Particles on every shape");
  add_whole_number_option(*command, "--seed", options->request.seed, kSeedRange, "Seed of the template's start and the model's draws");
  command->add_flag("--no-scale", options->no_scale, "Model: align by rotation and translation only");
  add_whole_number_option(*command, "--samples", options->request.samples, WholeRange{1, 1000000},
                          "Model: shapes drawn per number of modes, for specificity");
  command
      ->add_option("--deformation", options->deformation,
                   "How the template is moved onto each shape before its particles are carried over: graph (a "
                   "deformation graph, which bends at a joint) or smooth (a displacement smoothed over the template)")
      ->check(CLI::IsMember({deformation_name(TemplateDeformation::smooth), deformation_name(TemplateDeformation::graph)}))
      ->capture_default_str();
  add_whole_number_option(*command, "--refine-iterations", options->request.refinement.iterations, WholeRange{0, 100000},
                          "Iterations of the joint refinement after the transfer (0: the transfer alone)");
  command->add_option("--correspondence-weight", options->request.refinement.correspondence_weight,
                      "Refinement: the correspondence step's weight against the sampling step's (0: each shape "
                      "evened out on its own)")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  command->add_flag("--no-packing", options->no_packing,
                    "Refinement: end after the iterations, without the packing (each shape's particles pushed apart "
                    "for a growing radius, as `run` spreads them)");
  command->add_option("--packing-hold", options->request.refinement.packing_hold,
                      "Packing: the share of the correspondence weight it keeps (0: the evenest shapes, a looser "
                      "correspondence)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  command->add_option("--even-enough", options->request.refinement.even_enough,
                      "Then each shape keeps only as much of the refinement's evening as keeps its closest pair this "
                      "many spacings apart, its particles nearer where the transfer put them (0: as near as its holes "
                      "and the other shapes allow; 1: the refinement's places)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  add_whole_number_option(*command, "--threads", options->request.threads, kThreadRange,
                          "Threads per process for its shapes (0: the cores, shared among the ranks of a node); the "
                          "result is the same for any number");
  command->add_flag("-q,--quiet", options->request.quiet, "No progress lines");
  command->callback([options] { run_correspond_command(*options); });
}

}  // namespace meshparticles
