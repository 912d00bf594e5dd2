#include "particles/device_cavity_centres.hpp"

#include <algorithm>
#include <chrono>
#include <initializer_list>

#include "common/elapsed.hpp"
#include "common/user_error.hpp"
#include "opencl/program_cache.hpp"
#include "opencl/read_only_buffer.hpp"

namespace meshparticles {

namespace {

// One particle's cavity and its share of the scratch: cavity_task in
// kernels/cavity_centres.cl, the same layout.
struct CavityTask {
  std::uint32_t particle, region_start, region_size, near_start, near_size, further_start, further_size;
  std::uint32_t triangles_at, corners_at, sources_at, table_at, triangle_slots_at, vertex_slots_at;
};
static_assert(sizeof(CavityTask) == 52, "kernels/cavity_centres.cl reads cavity_task with this layout");
// The shared structs as the device lays them out (double on 8 bytes).
static_assert(sizeof(vec3d) == 24 && sizeof(ball_entry) == 8, "the device's layout of vec3d and ball_entry");
static_assert(sizeof(planar_source) == 56 && sizeof(cavity_found) == 72, "the device's layout of the shared structs");

// A GPU's work-group: a warp or two of particles.
constexpr std::size_t kGpuWorkGroupSize = 64;

}  // namespace

bool device_has_double_precision(const DeviceDescription& device) {
  // OpenCL 1.2 answers 0 without double precision; an older device may
  // refuse the question.
  try {
    return device.device.getInfo<CL_DEVICE_DOUBLE_FP_CONFIG>() != 0;
  } catch (const cl::Error&) {
    return false;
  }
}

DeviceCavityCentres::DeviceCavityCentres(const SurfaceMesh& mesh, const DeviceDescription& device)
    : fans_(vertex_triangles(mesh.triangles(), mesh.vertex_count())),
      surface_(mesh, fans_),
      device_name_(device.name),
      max_allocation_bytes_(device.max_allocation_bytes) {
  if (!device_has_double_precision(device)) {
    throw UserError("the evening's moves need double precision, which " + device.name + " lacks");
  }
  context_ = device_context(device.device);
  queue_ = cl::CommandQueue(context_, device.device);
  const cl::Program program = cached_program(device.device, {"cavity_centres.cl"}, {}, FloatMath::exact);
  kernel_ = cl::Kernel(program, "cavity_centres");
  work_group_size_ = device.is_gpu() ? std::min<std::size_t>({kGpuWorkGroupSize, device.max_work_group_size,
                                                              kernel_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(device.device)})
                                     : 1;
  positions_ = read_only_buffer(context_, surface_.positions());
  corners_ = read_only_buffer(context_, surface_.corners());
  fan_start_ = read_only_buffer(context_, fans_.offsets);
  fan_triangles_ = read_only_buffer(context_, fans_.triangles);
}

bool DeviceCavityCentres::fit(GrowingBuffer& buffer, std::size_t bytes) {
  return buffer.fit(bytes, [&](std::size_t room) { return cl::Buffer(context_, CL_MEM_READ_WRITE, room); });
}

void DeviceCavityCentres::send_balls(const ParticleBalls& balls) {
  const std::vector<ball_entry>& entries = balls.entries();
  const std::size_t bytes = std::max<std::size_t>(entries.size(), 1) * sizeof(ball_entry);
  if (fit(entries_, bytes) || balls.compactions() != compactions_seen_ || entries.size() < entries_sent_) {
    entries_sent_ = 0;
    compactions_seen_ = balls.compactions();
  }
  if (entries.size() > entries_sent_) {
    queue_.enqueueWriteBuffer(entries_.buffer(), CL_FALSE, entries_sent_ * sizeof(ball_entry),
                              (entries.size() - entries_sent_) * sizeof(ball_entry), entries.data() + entries_sent_);
  }
  entries_sent_ = entries.size();
}

std::optional<std::vector<CavityCentre>> DeviceCavityCentres::centres(std::span<const std::uint32_t> particles,
                                                                      const std::vector<Cavity>& cavities,
                                                                      const std::vector<vec3d>& points,
                                                                      const std::vector<std::uint32_t>& triangles,
                                                                      const ParticleBalls& balls) {
  const auto started = std::chrono::steady_clock::now();
  std::vector<CavityCentre> result;
  result.reserve(cavities.size());
  if (cavities.empty()) return result;
  if (balls.entries().size() * sizeof(ball_entry) > max_allocation_bytes_) {
    ++statistics_.sets_on_host;
    return std::nullopt;
  }
  send_balls(balls);
  const auto send = [&](GrowingBuffer& to, const auto& values) {
    const std::size_t bytes = values.size() * sizeof(values[0]);
    fit(to, bytes);
    if (bytes > 0) queue_.enqueueWriteBuffer(to.buffer(), CL_FALSE, 0, bytes, values.data());
  };
  send(points_, points);
  send(triangles_, triangles);
  send(ball_start_, balls.starts());
  send(ball_size_, balls.sizes());
  // The cavities in chunks whose scratch table fits a quarter of the
  // device's largest buffer (a chunk holds one cavity at least).
  const cavity_surface mesh = surface_.view();
  const std::size_t table_limit = std::max<std::size_t>(max_allocation_bytes_ / 4, 1) / sizeof(float);
  std::vector<CavityTask> tasks;
  std::vector<std::uint32_t> lists;
  std::vector<cavity_found> found;
  for (std::size_t first = 0; first < cavities.size();) {
    tasks.clear();
    lists.clear();
    std::size_t triangles_total = 0, corners_total = 0, sources_total = 0, table_total = 0;
    std::size_t triangle_slots_total = 0, vertex_slots_total = 0;  // two words a slot
    std::size_t last = first;
    for (; last < cavities.size(); ++last) {
      const Cavity& c = cavities[last];
      const cavity_scratch_size size = cavity_scratch_sizes(mesh, cavity_of(c));
      const std::size_t table = std::size_t(size.sources) * size.corners;
      if (last > first && table_total + table > table_limit) break;
      CavityTask task{};
      task.particle = particles[last];
      const auto append = [&](std::span<const std::uint32_t> list, std::uint32_t& start, std::uint32_t& count) {
        start = std::uint32_t(lists.size());
        count = std::uint32_t(list.size());
        lists.insert(lists.end(), list.begin(), list.end());
      };
      append(c.region, task.region_start, task.region_size);
      append(c.near, task.near_start, task.near_size);
      append(c.further, task.further_start, task.further_size);
      task.triangles_at = std::uint32_t(triangles_total);
      task.corners_at = std::uint32_t(corners_total);
      task.sources_at = std::uint32_t(sources_total);
      task.table_at = std::uint32_t(table_total);
      task.triangle_slots_at = std::uint32_t(triangle_slots_total);
      task.vertex_slots_at = std::uint32_t(vertex_slots_total);
      triangle_slots_total += 2 * std::size_t(size.triangle_slots);
      vertex_slots_total += 2 * std::size_t(size.vertex_slots);
      triangles_total += size.triangles;
      corners_total += size.corners;
      sources_total += size.sources;
      table_total += table;
      tasks.push_back(task);
    }
    send(tasks_, tasks);
    send(lists_, lists);
    const auto scratch = [&](GrowingBuffer& b, std::size_t bytes) { fit(b, bytes); };
    scratch(scratch_triangles_, triangles_total * sizeof(cl_uint));
    scratch(scratch_bounds_, triangles_total * sizeof(cl_double));
    scratch(scratch_triangle_slots_, triangle_slots_total * sizeof(cl_uint));
    scratch(scratch_vertex_slots_, vertex_slots_total * sizeof(cl_uint));
    scratch(scratch_vertices_, corners_total * sizeof(cl_uint));
    scratch(scratch_corner_rows_, corners_total * sizeof(cl_uint));
    scratch(scratch_ways_, corners_total * sizeof(cl_double));
    scratch(scratch_nearest_, corners_total * sizeof(cl_float));
    scratch(scratch_table_, table_total * sizeof(cl_float));
    scratch(scratch_planar_, sources_total * sizeof(planar_source));
    scratch(scratch_near_, sources_total * sizeof(cl_uint));
    scratch(found_, tasks.size() * sizeof(cavity_found));
    int arg = 0;
    kernel_.setArg(arg++, cl_uint(tasks.size()));
    const std::initializer_list<const cl::Buffer*> arguments = {
        &tasks_.buffer(), &lists_.buffer(), &positions_, &corners_, &fan_start_, &fan_triangles_,
        &triangles_.buffer(), &points_.buffer(), &entries_.buffer(), &ball_start_.buffer(), &ball_size_.buffer(),
        &scratch_triangles_.buffer(), &scratch_bounds_.buffer(), &scratch_triangle_slots_.buffer(),
        &scratch_vertex_slots_.buffer(), &scratch_vertices_.buffer(), &scratch_corner_rows_.buffer(),
        &scratch_ways_.buffer(), &scratch_nearest_.buffer(), &scratch_table_.buffer(), &scratch_planar_.buffer(),
        &scratch_near_.buffer(), &found_.buffer()};
    for (const cl::Buffer* b : arguments) {
      kernel_.setArg(arg++, *b);
    }
    // One work-item a group on a CPU device: PoCL runs a group's items in
    // step, and these go their own ways.
    const std::size_t group = work_group_size_;
    const std::size_t global = (tasks.size() + group - 1) / group * group;
    queue_.enqueueNDRangeKernel(kernel_, cl::NullRange, cl::NDRange(global), cl::NDRange(group));
    found.resize(tasks.size());
    queue_.enqueueReadBuffer(found_.buffer(), CL_TRUE, 0, found.size() * sizeof(cavity_found), found.data());
    for (const cavity_found& f : found) result.push_back(cavity_centre_found(f));
    ++statistics_.launches;
    first = last;
  }
  statistics_.cavities += cavities.size();
  statistics_.seconds += seconds_since(started);
  return result;
}

}  // namespace meshparticles
