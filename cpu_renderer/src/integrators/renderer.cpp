#include "safegi/cpu_renderer/renderer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <limits>
#include <mutex>
#include <optional>
#include <thread>
#include <unistd.h>

#include "integrators/bdpt.hpp"
#include "integrators/sppm.hpp"
#include "scene/camera.hpp"
#include "accel/geometry.hpp"
#include "integrators/integrator.hpp"
#include "lights/lights.hpp"
#include "film/pixel_filter.hpp"
#include "util/printable.hpp"
#include "integrators/sampler.hpp"
#include "film/splat_film.hpp"

namespace safegi::render {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kTileSize = 16;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A progress bar with ETA on stderr, redrawn in place on a terminal and
// printed as occasional lines otherwise.
class Progress {
 public:
  Progress(bool enabled, uint64_t total_work)
      : enabled_(enabled), terminal_(enabled && isatty(STDERR_FILENO)), total_(total_work), start_(Clock::now()) {
    if (enabled_) reporter_ = std::thread([this] { report_loop(); });
  }
  ~Progress() { finish(); }

  void advance(uint64_t work) { done_.fetch_add(work, std::memory_order_relaxed); }
  void set_total(uint64_t total) { total_.store(total, std::memory_order_relaxed); }

  void finish() {
    if (!reporter_.joinable()) return;
    {
      std::lock_guard lock(mutex_);
      finished_ = true;
    }
    wake_.notify_all();
    reporter_.join();
    draw(true);
    std::fputc('\n', stderr);
  }

 private:
  void report_loop() {
    std::unique_lock lock(mutex_);
    int last_decile = -1;
    while (!wake_.wait_for(lock, std::chrono::milliseconds(terminal_ ? 100 : 1000), [this] { return finished_; })) {
      if (terminal_) {
        draw(false);
      } else {
        int decile = static_cast<int>(fraction() * 10);
        if (decile != last_decile) {
          last_decile = decile;
          draw(false);
          std::fputc('\n', stderr);
        }
      }
    }
  }

  double fraction() const {
    uint64_t total = total_.load(std::memory_order_relaxed);
    return total == 0 ? 1.0 : std::min(1.0, static_cast<double>(done_.load(std::memory_order_relaxed)) / total);
  }

  void draw(bool final) {
    constexpr int kWidth = 40;
    double f = final ? 1.0 : fraction();
    double elapsed = seconds_since(start_);
    int filled = static_cast<int>(f * kWidth);
    char bar[kWidth + 1];
    for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
    bar[kWidth] = '\0';
    if (final || f <= 0) {
      std::fprintf(stderr, "%s[%s] %5.1f%%  %.1fs", terminal_ ? "\r" : "", bar, f * 100, elapsed);
    } else {
      double eta = elapsed * (1 - f) / f;
      std::fprintf(stderr, "%s[%s] %5.1f%%  %.1fs, ETA %.1fs ", terminal_ ? "\r" : "", bar, f * 100, elapsed, eta);
    }
    std::fflush(stderr);
  }

  bool enabled_, terminal_;
  std::atomic<uint64_t> total_;
  std::atomic<uint64_t> done_{0};
  Clock::time_point start_;
  std::thread reporter_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool finished_ = false;
};

}  // namespace

ImageSize parse_resolution(const std::string& text, const std::string& option) {
  // Digits, 'x', digits; up to 9 digits a side, so that the limit, not an overflow, speaks for long numbers.
  const std::size_t x = text.find('x');
  auto side = [&](std::string_view digits) {
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string_view::npos) return -1;
    return std::stoi(std::string(digits));
  };
  const std::string_view whole(text);
  const int width = x == std::string::npos ? -1 : side(whole.substr(0, x));
  const int height = x == std::string::npos ? -1 : side(whole.substr(x + 1));
  if (width < 0 || height < 0)
    throw CommandLineError(option + ": expected WIDTHxHEIGHT in pixels (e.g. 640x480), got '" + printable(text, 40) + "'");
  for (auto [name, value] : {std::pair{"width", width}, std::pair{"height", height}})
    if (value < 1 || value > kMaxImageSide)
      throw CommandLineError(option + ": " + text + ": the " + name + " must be 1 to " + std::to_string(kMaxImageSide) +
                             " pixels, got " + std::to_string(value));
  return {width, height};
}

bool splats_samples(const PixelFilter& filter) {
  return filter.mode == PixelFilterMode::splat && !PixelFilterSampler::is_plain_box(filter);
}

bool sums_on_first_process(const RenderSettings& settings) {
  return splats_samples(settings.filter) || settings.integrator == IntegratorType::bdpt;
}

std::vector<PixelRect> render_tiles(int width, int height) {
  std::vector<PixelRect> tiles;
  for (int y = 0; y < height; y += kTileSize)
    for (int x = 0; x < width; x += kTileSize)
      tiles.push_back({x, y, std::min(x + kTileSize, width), std::min(y + kTileSize, height)});
  return tiles;
}

Image render(const Scene& scene, const RenderOptions& options, RenderStats* stats) {
  if (options.settings.integrator == IntegratorType::sppm) return render_sppm(scene, options, stats);
  Clock::time_point start = Clock::now();
  const RenderSettings& settings = options.settings;
  CropWindow window = options.crop.value_or(CropWindow{0, 0, settings.width, settings.height});
  window.x = std::clamp(window.x, 0, settings.width);
  window.y = std::clamp(window.y, 0, settings.height);
  window.width = std::clamp(window.width, 0, settings.width - window.x);
  window.height = std::clamp(window.height, 0, settings.height - window.y);

  const int hardware_threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  Geometry geometry(scene, options.threads > 0 ? options.threads : hardware_threads);
  // The bidirectional path tracer's light subpaths choose lights by power, and so do its light samples.
  const bool bidirectional = settings.integrator == IntegratorType::bdpt;
  Lights lights(scene, bidirectional ? LightStrategy::power : settings.light_strategy);
  CameraRays camera(scene.camera, settings.width, settings.height);
  Integrator integrator(scene, geometry, lights, settings);
  std::optional<Bdpt> bdpt;
  if (bidirectional) bdpt.emplace(scene, geometry, lights, settings);

  // How samples make pixels: uniform in their pixel (the plain box), offset
  // by the filter and kept in their pixel, or splatted over the filter's
  // footprint (pbrt-v3's way; then pixels just outside the window are
  // sampled too).
  const PixelRect window_rect{window.x, window.y, window.x + window.width, window.y + window.height};
  std::optional<PixelFilterSampler> filter;
  std::optional<SplatFilm> splat_film;
  if (splats_samples(settings.filter))
    splat_film.emplace(settings.filter, window_rect);
  else if (!PixelFilterSampler::is_plain_box(settings.filter))
    filter.emplace(settings.filter);
  const PixelRect sampled = splat_film ? splat_film->sample_bounds() : window_rect;
  // Light tracing's contributions (bdpt), wherever on the film they land.
  std::optional<LightImage> light_image;
  if (bdpt) light_image.emplace(window_rect);

  // This process's tiles, in image coordinates; with a partition, every
  // parts()-th of them.
  RenderPartition* partition = options.partition;
  std::vector<PixelRect> tiles;
  uint64_t pixel_count = 0;
  std::vector<PixelRect> sampled_tiles = render_tiles(sampled.x1 - sampled.x0, sampled.y1 - sampled.y0);
  for (size_t t = 0; t < sampled_tiles.size(); ++t) {
    if (partition && static_cast<int>(t % partition->parts()) != partition->part()) continue;
    const PixelRect& r = sampled_tiles[t];
    tiles.push_back({sampled.x0 + r.x0, sampled.y0 + r.y0, sampled.x0 + r.x1, sampled.y0 + r.y1});
    pixel_count += static_cast<uint64_t>(r.x1 - r.x0) * (r.y1 - r.y0);
  }

  // Per-pixel sums in double; every pixel's samples are added in sample order,
  // so the result does not depend on which thread rendered which tile. With
  // a pixel filter, the sums of the samples' weights too.
  std::vector<double> sums(splat_film ? 0 : 3 * static_cast<size_t>(window.width) * window.height, 0.0);
  std::vector<double> weight_sums(filter ? static_cast<size_t>(window.width) * window.height : 0, 0.0);
  int thread_count = options.threads > 0 ? options.threads : hardware_threads;
  thread_count = std::max(1, std::min<int>(thread_count, static_cast<int>(std::max<size_t>(tiles.size(), 1))));

  const bool budgeted = options.time_budget_seconds > 0;
  const int spp_cap = settings.spp;
  // With a time budget, samples are added in passes; without, one pass renders all.
  int pass_spp = budgeted ? 1 : spp_cap;
  // bdpt: passes short enough that the splats waiting stay few (LightImage::kPassSpp).
  const int most_pass_spp = bdpt ? LightImage::kPassSpp : std::numeric_limits<int>::max();
  pass_spp = std::min(pass_spp, most_pass_spp);
  Progress progress(options.progress, pixel_count * static_cast<uint64_t>(spp_cap));

  std::vector<RayCounters> counters(thread_count);
  std::vector<uint64_t> invalid(thread_count, 0);
  int spp_done = 0;
  while (spp_done < spp_cap) {
    int pass_begin = spp_done;
    int pass_end = std::min(spp_cap, spp_done + pass_spp);
    Clock::time_point pass_start = Clock::now();
    std::atomic<size_t> next_tile{0};
    if (splat_film) splat_film->begin_pass(tiles.size(), thread_count);
    if (light_image) light_image->begin_pass(tiles.size(), thread_count);
    auto worker = [&](int thread_index) {
      RayCounters& counter = counters[thread_index];
      for (size_t t = next_tile++; t < tiles.size(); t = next_tile++) {
        const PixelRect& tile = tiles[t];
        std::optional<SplatFilm::TileSplats> splats;
        if (splat_film) {
          splat_film->wait_for_room(t);
          splats = splat_film->tile_splats(tile);
        }
        std::vector<bdpt::Splat> light_splats;
        if (light_image) light_image->wait_for_room(t);
        for (int y = tile.y0; y < tile.y1; ++y) {
          for (int x = tile.x0; x < tile.x1; ++x) {
            for (int s = pass_begin; s < pass_end; ++s) {
              Sampler sampler(options.seed, static_cast<uint32_t>(x), static_cast<uint32_t>(y), static_cast<uint32_t>(s));
              const Sample2 film = sampler.next_2d();
              Real film_x = static_cast<Real>(x) + film.u, film_y = static_cast<Real>(y) + film.v;
              double weight = 1;
              if (filter) {
                const PixelFilterSampler::Sample offset = filter->sample(film.u, film.v);
                weight = offset.weight;
                film_x = static_cast<Real>(x) + Real(0.5) + offset.dx;
                film_y = static_cast<Real>(y) + Real(0.5) + offset.dy;
              }
              const TimedRay ray = camera.generate_at(film_x, film_y, sampler);
              ++counter.camera;
              sg::vec3_rep L = sg::raw(bdpt ? bdpt->radiance(ray, sampler, counter, light_splats)
                                            : integrator.radiance(ray, sampler, counter));  // W/(m2 sr)
              if (!std::isfinite(L.r) || !std::isfinite(L.g) || !std::isfinite(L.b)) {
                ++invalid[thread_index];
                continue;
              }
              if (splats) {
                splats->add(film_x, film_y, {L.r, L.g, L.b});
                continue;
              }
              const size_t pixel = static_cast<size_t>(y - window.y) * window.width + (x - window.x);
              double* sum = &sums[3 * pixel];
              sum[0] += weight * L.r;
              sum[1] += weight * L.g;
              sum[2] += weight * L.b;
              if (filter) weight_sums[pixel] += weight;
            }
          }
        }
        if (splats) splat_film->add_in_order(t, std::move(*splats));
        if (light_image) light_image->add_in_order(t, std::move(light_splats));
        progress.advance(static_cast<uint64_t>(tile.x1 - tile.x0) * (tile.y1 - tile.y0) * (pass_end - pass_begin));
      }
    };
    std::vector<std::thread> workers;
    for (int i = 1; i < thread_count; ++i) workers.emplace_back(worker, i);
    worker(0);
    for (std::thread& w : workers) w.join();
    spp_done = pass_end;

    if (budgeted) {
      double pass_seconds = std::max(1e-6, seconds_since(pass_start));
      if (partition) pass_seconds = partition->slowest_pass_seconds(pass_seconds);
      double elapsed = seconds_since(start);
      double per_sample = pass_seconds / (pass_end - pass_begin);
      double remaining = options.time_budget_seconds - elapsed;
      // Grow passes so the budget is met with few synchronisation points; 0 stops.
      int next_pass_spp =
          remaining < per_sample
              ? 0
              : std::max(1, std::min(static_cast<int>(remaining / per_sample / 2), 2 * (pass_end - pass_begin)));
      next_pass_spp = std::min(next_pass_spp, most_pass_spp);
      if (partition) next_pass_spp = partition->next_pass_spp_of_first(next_pass_spp);
      if (next_pass_spp == 0) break;
      pass_spp = next_pass_spp;
      double projected = (spp_done + std::min(spp_cap - spp_done, static_cast<int>(remaining / per_sample))) ;
      progress.set_total(static_cast<uint64_t>(projected) * pixel_count);
    }
  }
  progress.finish();

  // bdpt: every process's pixels on the first (sums_on_first_process), the others' tiles zeros in each sum.
  if (light_image && partition && !splat_film) {
    partition->sum_to_first(sums);
    if (filter) partition->sum_to_first(weight_sums);
  }
  Image image;
  image.width = window.width;
  image.height = window.height;
  if (splat_film) {
    // Every process's splats, added on the first (the others return theirs unused).
    if (partition) partition->sum_to_first(splat_film->sums());
    image.rgb = splat_film->pixels();
  } else {
    image.rgb.resize(sums.size());
    double scale = spp_done > 0 ? 1.0 / spp_done : 0.0;
    for (size_t i = 0; i < sums.size(); ++i)
      image.rgb[i] = filter ? filtered_pixel(sums[i], weight_sums[i / 3]) : static_cast<float>(sums[i] * scale);
  }
  if (light_image) {
    // pbrt-v3's splat scale, 1/spp: each camera sample traced one light
    // path, spp per pixel of the whole image, whose camera density the splats
    // hold. A crop traces them for its own pixels only: fewer, each counting more.
    if (partition) partition->sum_to_first(light_image->sums());
    const double traced_pixels = static_cast<double>(sampled.x1 - sampled.x0) * (sampled.y1 - sampled.y0);
    const double image_pixels = static_cast<double>(settings.width) * settings.height;
    const double scale = spp_done > 0 ? image_pixels / (traced_pixels * spp_done) : 0.0;
    for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] += static_cast<float>(light_image->sums()[i] * scale);
  }
  if (settings.film_scale != 1)
    for (float& value : image.rgb) value = static_cast<float>(value * settings.film_scale);

  if (stats) {
    *stats = RenderStats{};
    for (int i = 0; i < thread_count; ++i) {
      stats->camera_rays += counters[i].camera;
      stats->extension_rays += counters[i].extension;
      stats->shadow_rays += counters[i].shadow;
      stats->invalid_samples += invalid[i];
    }
    stats->samples_per_pixel = spp_done;
    stats->threads = thread_count;
    stats->seconds = seconds_since(start);
  }
  return image;
}

}  // namespace safegi::render
