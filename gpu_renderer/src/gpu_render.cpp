#include "gpu_render.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <type_traits>
#include <vector>

#include "safegi/runtime_vk/runtime_vk.hpp"
#include "scene_packing.hpp"

namespace safegi::gpu {
namespace {

// One storage buffer of any element type, kept alive while the pipeline uses it.
struct AnyBuffer {
  virtual ~AnyBuffer() = default;
};
template <class T>
struct TypedBuffer : AnyBuffer {
  vk::storage_buffer<T> buffer;
  TypedBuffer(vk::Context& context, std::span<const T> values) : buffer(context, values.size()) {
    if (!values.empty()) buffer.upload(values);
  }
};

constexpr std::uint32_t kGroupSize = 8;  // path_tracer.comp's local_size_x and _y

void set_frame_constants(const vk::ComputePipeline& pipeline, vk::block_data& block, const FrameValues& frame) {
  block.set(pipeline.member<PointWorld>("frame.cameraPosition"), frame.camera_position);
  block.set(pipeline.member<DirectionWorld>("frame.cameraForward"), frame.camera_forward);
  block.set(pipeline.member<DirectionWorld>("frame.cameraRight"), frame.camera_right);
  block.set(pipeline.member<DirectionWorld>("frame.cameraUp"), frame.camera_up);
  block.set(pipeline.member<Radiance>("frame.environmentRadiance"), frame.environment_radiance);
  block.set(pipeline.member<float>("frame.imageHalfWidth"), frame.image_half_width);
  block.set(pipeline.member<float>("frame.imageHalfHeight"), frame.image_half_height);
  block.set(pipeline.member<Length>("frame.rayOffset"), frame.ray_offset);
  block.set(pipeline.member<std::uint32_t>("frame.imageWidth"), frame.image_width);
  block.set(pipeline.member<std::uint32_t>("frame.imageHeight"), frame.image_height);
  block.set(pipeline.member<std::uint32_t>("frame.triangleRoot"), frame.triangle_root);
  block.set(pipeline.member<std::uint32_t>("frame.sphereRoot"), frame.sphere_root);
  block.set(pipeline.member<std::uint32_t>("frame.lightCount"), frame.light_count);
  block.set(pipeline.member<std::uint32_t>("frame.maxDepth"), frame.max_depth);
  block.set(pipeline.member<std::uint32_t>("frame.rouletteDepth"), frame.roulette_depth);
  block.set(pipeline.member<std::uint32_t>("frame.environmentLight"), frame.environment_light);
  block.set(pipeline.member<Length>("frame.lensRadius"), frame.lens_radius);
  block.set(pipeline.member<Length>("frame.focusDistance"), frame.focus_distance);
  block.set(pipeline.member<std::uint32_t>("frame.environmentWidth"), frame.environment_width);
  block.set(pipeline.member<std::uint32_t>("frame.environmentHeight"), frame.environment_height);
  block.set(pipeline.member<DirectionWorld>("frame.skyAxisX"), frame.sky_axis_x);
  block.set(pipeline.member<DirectionWorld>("frame.skyAxisY"), frame.sky_axis_y);
  block.set(pipeline.member<DirectionWorld>("frame.skyAxisZ"), frame.sky_axis_z);
  block.set(pipeline.member<std::uint32_t>("frame.materialNumbersFirst"), frame.material_numbers_first);
  block.set(pipeline.member<std::uint32_t>("frame.lightConeFirst"), frame.light_cone_first);
  block.set(pipeline.member<std::uint32_t>("frame.lightCdfFirst"), frame.light_cdf_first);
  block.set(pipeline.member<std::uint32_t>("frame.environmentRowCdfFirst"), frame.environment_row_cdf_first);
  block.set(pipeline.member<std::uint32_t>("frame.environmentColumnCdfFirst"), frame.environment_column_cdf_first);
  block.set(pipeline.member<std::uint32_t>("frame.environmentDensityFirst"), frame.environment_density_first);
  block.set(pipeline.member<std::uint32_t>("frame.triangleUvFirst"), frame.triangle_uv_first);
  block.set(pipeline.member<std::uint32_t>("frame.textureMappingFirst"), frame.texture_mapping_first);
  block.set(pipeline.member<std::uint32_t>("frame.textureInfoFirst"), frame.texture_info_first);
}

std::string beside_program_or(const char* file, const char* build_path) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path beside = self.parent_path() / file;
    if (std::filesystem::exists(beside)) return beside.string();
  }
  return build_path;
}

}  // namespace

std::string default_spirv_file() { return beside_program_or("path_tracer.spv", SAFEGI_GPU_SPIRV); }
std::string default_symbols_file() { return beside_program_or("path_tracer.json", SAFEGI_GPU_SYMBOLS); }

render::Image render_on_gpu(const render::Scene& scene, const GpuRenderOptions& options, GpuRenderStats& stats) {
  const int width = options.width > 0 ? options.width : scene.settings.width;
  const int height = options.height > 0 ? options.height : scene.settings.height;
  const int spp = options.spp > 0 ? options.spp : scene.settings.spp;
  const PackedScene packed = pack_scene(scene, width, height);

  vk::ContextOptions context_options;
  context_options.device = options.device;
  vk::Context context(context_options);
  vk::ComputePipeline pipeline(context, vk::ComputeShader{vk::read_spirv_file(options.spirv_file),
                                                          vk::read_symbol_table_file(options.symbols_file),
                                                          "path_tracer.comp"});

  std::vector<std::unique_ptr<AnyBuffer>> buffers;
  for_each_array(packed, [&](std::string_view name, const auto& values) {
    using T = typename std::decay_t<decltype(values)>::value_type;
    auto buffer = std::make_unique<TypedBuffer<T>>(context, std::span<const T>(values));
    pipeline.bind(pipeline.storage_array<T>(name), buffer->buffer);
    buffers.push_back(std::move(buffer));
  });
  vk::block_data constants = pipeline.block("FrameConstants");
  set_frame_constants(pipeline, constants, packed.frame);
  vk::block_buffer constants_buffer(context, constants);
  pipeline.bind(pipeline.block_binding("FrameConstants"), constants_buffer);

  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  vk::storage_buffer<Radiance> film(context, std::vector<Radiance>(pixels));
  vk::storage_buffer<std::uint32_t> ray_counts(context, std::vector<std::uint32_t>(pixels, 0u));
  pipeline.bind(pipeline.storage_array<Radiance>("FilmSum.radianceSum"), film);
  pipeline.bind(pipeline.storage_array<std::uint32_t>("FilmRays.rayCount"), ray_counts);

  const auto sample_index = pipeline.push_constant<std::uint32_t>("sampleIndex");
  const auto seed = pipeline.push_constant<std::uint32_t>("seed");
  vk::block_data pass = pipeline.push_constants();
  pass.set(seed, options.seed);
  const std::uint32_t groups_x = (static_cast<std::uint32_t>(width) + kGroupSize - 1) / kGroupSize;
  const std::uint32_t groups_y = (static_cast<std::uint32_t>(height) + kGroupSize - 1) / kGroupSize;

  const auto start = std::chrono::steady_clock::now();
  for (int s = 0; s < spp; ++s) {
    pass.set(sample_index, static_cast<std::uint32_t>(s));
    pipeline.dispatch(pass, groups_x, groups_y);
    if (options.progress) std::fprintf(stderr, "\rsample %d/%d", s + 1, spp);
  }
  const std::vector<Radiance> sums = film.read_back();
  const std::vector<std::uint32_t> rays = ray_counts.read_back();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.progress) std::fprintf(stderr, "\n");

  render::Image image{width, height, std::vector<float>(3 * pixels)};
  for (std::size_t i = 0; i < pixels; ++i) {
    const Radiance mean = sums[i] / static_cast<float>(spp);
    const auto rep = sg::raw(mean);  // in W·m⁻²·sr⁻¹, the reference unit
    image.rgb[3 * i] = rep.x;
    image.rgb[3 * i + 1] = rep.y;
    image.rgb[3 * i + 2] = rep.z;
  }
  stats.width = width;
  stats.height = height;
  stats.spp = spp;
  stats.rays = 0;
  for (std::uint32_t r : rays) stats.rays += r;
  stats.device = vk::describe(context.info());
  stats.unsupported = packed.unsupported;
  return image;
}

}  // namespace safegi::gpu
