// meshparticles: spreads particles evenly over triangle meshes.
// This file only wires the subcommands together and maps failures to exit
// codes: 0 success, 2 bad input or arguments, 3 no OpenCL runtime, 1 a bug.
#include <iostream>

#include "cli/command_guide.hpp"
#include "cli/commands.hpp"
#include "common/text_format.hpp"
#include "common/version.hpp"
#include "launch/failure.hpp"
#include "options/option_values.hpp"
#include "options/run_option_table.hpp"

namespace meshparticles {

void add_device_option(CLI::App& command, std::string& device_request) {
  command.add_option("--device", device_request, run_option("device").help);
}

void add_strict_option(CLI::App& command, MeshReadOptions& read) {
  command.add_flag("--strict", read.strict, run_option("strict").help);
}

}  // namespace meshparticles

int main(int argc, char** argv) {
  using namespace meshparticles;
  CLI::App app{"meshparticles: spread particles evenly over triangulated surface meshes"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "meshparticles " + program_version());
  add_info_command(app);
  add_devices_command(app);
  add_generate_command(app);
  add_geodesics_command(app);
  add_run_command(app);
  add_batch_command(app);
  add_sweep_command(app);
  add_bench_command(app);
  add_quality_command(app);
  add_compare_command(app);
  add_model_command(app);
  add_correspond_command(app);
  add_completion_command(app);
  refuse_unusable_values(app);
  if (argc == 1) {
    std::cerr << short_usage(app);
    return 2;
  }
  // CLI11 alone would answer a misspelt command with "A subcommand is required".
  if (const auto error = unknown_command_error(app, argv[1])) {
    std::cerr << "meshparticles: error: " << one_line(*error) << "\n";
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForVersion& version) {
    return app.exit(version);
  } catch (const CLI::ParseError& error) {
    std::cerr << "meshparticles: error: " << one_line(error.what()) << " (see --help)\n";
    return 2;
  } catch (...) {
    const Failure failure = describe_failure(std::current_exception());
    std::cerr << "meshparticles: " << (failure.internal ? "internal error: " : "error: ") << failure.message << "\n";
    return failure.exit_code;
  }
  return 0;
}
