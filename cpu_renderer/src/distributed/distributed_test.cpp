// safegi-render under mpirun (distributed.cpp): the image is bit-identical to
// the single process's for 1 to 4 ranks, a time budget stops every rank at
// the same pass, statistics add up, and a failing or dying rank ends the job
// with one clear error instead of a hang.
//
// The ranks run on this machine only: the environment below keeps Open MPI on
// shared memory and loopback (no network needed), lets it start more ranks
// than cores, and lets it run as root (CI does).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sys/wait.h>
#include <unistd.h>

#include "safegi/cpu_renderer/image_io.hpp"

namespace safegi::render {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = SAFEGI_SCENES_DIR;

void use_local_open_mpi() {
  for (auto [name, value] : {std::pair{"OMPI_ALLOW_RUN_AS_ROOT", "1"}, {"OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1"},
                             {"OMPI_MCA_rmaps_base_oversubscribe", "1"}, {"OMPI_MCA_btl", "self,vader"},
                             {"OMPI_MCA_btl_vader_single_copy_mechanism", "none"}, {"OMPI_MCA_pml", "ob1"},
                             {"OMPI_MCA_oob_tcp_if_include", "lo"}, {"OMPI_MCA_plm_rsh_agent", ""}})
    setenv(name, value, 0);  // a caller's own setting wins
}

std::string read_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Result {
  int exit_code = -1;  // -1: killed by a signal
  std::string out, err;
  double seconds = 0;
};

class Distributed : public ::testing::Test {
 protected:
  void SetUp() override {
    use_local_open_mpi();
    directory_ = fs::temp_directory_path() /
                 ("safegi-distributed-" + std::to_string(::getpid()) + "-" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  // Runs `safegi-render ARGS` under mpirun with `ranks` ranks (0: without
  // mpirun), bounded in time: a hang becomes a failure, not a stuck suite.
  Result render(int ranks, const std::string& args, const std::string& environment = "") {
    std::string launcher = ranks > 0 ? std::string(SAFEGI_MPIEXEC) + " -np " + std::to_string(ranks) + " " : "";
    fs::path out = directory_ / "stdout.txt", err = directory_ / "stderr.txt";
    std::string command = environment + " timeout -k 5 60 " + launcher + SAFEGI_RENDER_CHECKED + " " + args + " > \"" +
                          out.string() + "\" 2> \"" + err.string() + "\"";
    auto start = std::chrono::steady_clock::now();
    int status = std::system(command.c_str());
    Result result;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_file(out);
    result.err = read_file(err);
    return result;
  }

  fs::path directory_;
};

// The job failed by itself: not killed by the test's timeout (a hang).
void expect_failed_without_hanging(const Result& job) {
  EXPECT_NE(job.exit_code, 0) << job.err;
  EXPECT_NE(job.exit_code, 124) << "the job hung until the test's timeout\n" << job.err;
  EXPECT_LT(job.seconds, 55.0) << "the job hung until the test's timeout\n" << job.err;
}

size_t count(const std::string& text, const std::string& part) {
  size_t n = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

std::string json_field(const std::string& stats, const std::string& name) {
  std::smatch match;
  if (!std::regex_search(stats, match, std::regex("\"" + name + "\": ([^,}]+)"))) return "(missing)";
  return match[1];
}

// One scene and options, rendered by one process and by mpirun with each rank count.
struct Case {
  const char* name;
  const char* scene;
  const char* options;
  std::vector<int> ranks;
};

void PrintTo(const Case& c, std::ostream* out) { *out << c.name; }

class DistributedImages : public Distributed, public ::testing::WithParamInterface<Case> {};

// Each pixel is rendered whole by one rank and copied to rank 0, so the image
// files equal the single process's byte for byte: PFM (the floats) and PNG;
// the EXR's pixels (its header holds the time of writing).
TEST_P(DistributedImages, EqualTheSingleProcessImageBitForBit) {
  const Case& c = GetParam();
  auto args = [&](const std::string& output) {
    return "\"" + (kScenes / c.scene).string() + "\" " + c.options + " --threads 1 -q --stats --pfm -o \"" +
           (directory_ / output).string() + "\"";
  };
  Result single = render(0, args("single"));
  ASSERT_EQ(single.exit_code, 0) << single.err;
  std::string single_pfm = read_file(directory_ / "single.pfm");
  std::string single_png = read_file(directory_ / "single.png");
  Image single_exr = read_image(directory_ / "single.exr");
  ASSERT_GT(single_pfm.size(), 100u);
  for (int ranks : c.ranks) {
    std::string name = "ranks" + std::to_string(ranks);
    Result job = render(ranks, args(name));
    ASSERT_EQ(job.exit_code, 0) << name << "\n" << job.err;
    EXPECT_TRUE(read_file(directory_ / (name + ".pfm")) == single_pfm) << c.name << ", " << ranks << " ranks: PFM";
    EXPECT_TRUE(read_file(directory_ / (name + ".png")) == single_png) << c.name << ", " << ranks << " ranks: PNG";
    Image exr = read_image(directory_ / (name + ".exr"));
    ASSERT_EQ(exr.rgb.size(), single_exr.rgb.size());
    EXPECT_EQ(std::memcmp(exr.rgb.data(), single_exr.rgb.data(), exr.rgb.size() * sizeof(float)), 0)
        << c.name << ", " << ranks << " ranks: EXR pixels";
    // --stats adds up the ranks: the same rays as one process, one thread each.
    EXPECT_EQ(json_field(job.out, "ranks"), std::to_string(ranks)) << job.out;
    EXPECT_EQ(json_field(job.out, "threads"), std::to_string(ranks)) << job.out;
    for (const char* field : {"spp", "samples", "camera_rays", "extension_rays", "shadow_rays", "invalid_samples"})
      EXPECT_EQ(json_field(job.out, field), json_field(single.out, field)) << field << "\n" << job.out;
    // The progress bar and the summary are rank 0's alone (-q hides neither errors nor warnings).
    EXPECT_EQ(job.err, "") << name;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, DistributedImages,
    ::testing::Values(
        Case{"cornell_box", "cornell-box/cornell-box.json", "--resolution 48x40 --spp 4", {1, 2, 4}},
        Case{"motion_blur_light_samples", "motion-blur.json", "--resolution 40x32 --spp 3 --mis off --light-samples 2",
             {2, 4}},
        Case{"depth_of_field_direct", "depth-of-field.json", "--resolution 40x32 --spp 3 --integrator direct", {2, 4}},
        Case{"moving_light_no_roulette", "moving-light.json", "--resolution 40x32 --spp 2 --rr off --max-depth 4 --seed 7",
             {2, 4}},
        // A crop window not on the tile grid, and three ranks.
        Case{"phong_crop", "phong.json", "--resolution 64x48 --crop 5,3,37,29 --spp 2 --rr-depth 0", {3}},
        // More ranks than tiles: two ranks render nothing and still take part.
        Case{"more_ranks_than_tiles", "many-lights.json", "--resolution 20x12 --spp 2", {4}}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

// --time-budget: rank 0 decides after every pass, from the slowest rank's
// time, and all ranks stop at that pass. The image is then the single
// process's with the same number of samples per pixel (whatever the passes).
TEST_F(Distributed, TimeBudgetStopsEveryRankAtTheSamePass) {
  std::string scene = "\"" + (kScenes / "cornell-box/cornell-box.json").string() + "\" --resolution 32x32 --threads 1 -q --pfm";
  Result job = render(3, scene + " --time-budget 0.5 --spp 100000 --stats -o \"" + (directory_ / "budget").string() + "\"");
  ASSERT_EQ(job.exit_code, 0) << job.err;
  int spp = std::atoi(json_field(job.out, "spp").c_str());
  ASSERT_GE(spp, 2) << "several passes expected in 0.5 s\n" << job.out;
  Result single = render(0, scene + " --spp " + std::to_string(spp) + " -o \"" + (directory_ / "fixed").string() + "\"");
  ASSERT_EQ(single.exit_code, 0) << single.err;
  EXPECT_TRUE(read_file(directory_ / "budget.pfm") == read_file(directory_ / "fixed.pfm")) << spp << " spp";
}

// Splatted (a sample adds to pixels of other ranks' tiles), the ranks' sums are
// added on rank 0: the single process's image, to rounding (the sums add in
// another order).
TEST_F(Distributed, SplattedFilterSumsTheRanksPixels) {
  std::string text = read_file(kScenes / "phong.json");
  const std::string render_section = R"("render": {)";
  text.replace(text.find(render_section), render_section.size(),
               render_section + R"( "filter": {"type": "gaussian", "mode": "splat"},)");
  const std::filesystem::path scene = directory_ / "splat.json";
  std::ofstream(scene) << text;
  auto args = [&](const std::string& output) {
    return "\"" + scene.string() + "\" --resolution 40x36 --spp 2 --threads 1 -q -o \"" + (directory_ / output).string() + "\"";
  };
  Result single = render(0, args("single"));
  ASSERT_EQ(single.exit_code, 0) << single.err;
  Result job = render(3, args("ranks3"));
  ASSERT_EQ(job.exit_code, 0) << job.err;
  const Image one = read_image(directory_ / "single.exr"), three = read_image(directory_ / "ranks3.exr");
  ASSERT_EQ(one.rgb.size(), three.rgb.size());
  for (size_t i = 0; i < one.rgb.size(); ++i) EXPECT_NEAR(three.rgb[i], one.rgb[i], 1e-5f * (1 + one.rgb[i])) << i;
}

// The bidirectional path tracer's light tracing splats onto any rank's pixels:
// the ranks' sums, camera and light, are added on rank 0, the single
// process's image to rounding.
TEST_F(Distributed, BdptSumsTheRanksPixels) {
  auto args = [&](const std::string& output) {
    return "\"" + (kScenes / "cornell-box" / "cornell-box.json").string() +
           "\" --integrator bdpt --max-depth 4 --resolution 40x36 --spp 2 --threads 1 -q -o \"" +
           (directory_ / output).string() + "\"";
  };
  Result single = render(0, args("single"));
  ASSERT_EQ(single.exit_code, 0) << single.err;
  Result job = render(3, args("ranks3"));
  ASSERT_EQ(job.exit_code, 0) << job.err;
  const Image one = read_image(directory_ / "single.exr"), three = read_image(directory_ / "ranks3.exr");
  ASSERT_EQ(one.rgb.size(), three.rgb.size());
  for (size_t i = 0; i < one.rgb.size(); ++i) EXPECT_NEAR(three.rgb[i], one.rgb[i], 1e-5f * (1 + one.rgb[i])) << i;
}

// A scene that fails to load on every rank: the single process's message, once.
TEST_F(Distributed, SceneErrorIsPrintedOnce) {
  fs::path scene = directory_ / "bad.json";
  std::ofstream(scene) << R"({"camera": {"position": "1 W"}})";
  std::string expected = "error: " + scene.string() + ": camera.position: expected 3 components of length (e.g. m), got \"1 W\"\n";
  Result job = render(4, scene.string() + " -q -o " + (directory_ / "out").string());
  expect_failed_without_hanging(job);
  EXPECT_EQ(count(job.err, "error: "), 1u) << job.err;
  EXPECT_NE(job.err.find(expected), std::string::npos) << job.err;
  // So is a bad option (every rank parses the same command line).
  Result option = render(4, scene.string() + " --spp 0");
  expect_failed_without_hanging(option);
  EXPECT_EQ(count(option.err, "--spp"), 1u) << option.err;
}

// One rank's setup fails (test hook): every rank stops before rendering, and
// the one error names the rank.
TEST_F(Distributed, OneRanksSetupErrorNamesTheRank) {
  std::string scene = "\"" + (kScenes / "cornell-box/cornell-box.json").string() + "\" --resolution 16x16 --spp 1 -q";
  Result job = render(4, scene + " -o \"" + (directory_ / "out").string() + "\"", "SAFEGI_RENDER_TEST_FAULT=setup:2");
  expect_failed_without_hanging(job);
  EXPECT_EQ(count(job.err, "error: "), 1u) << job.err;
  EXPECT_NE(job.err.find("error: rank 2 of 4: test fault: rank 2's setup fails\n"), std::string::npos) << job.err;
  EXPECT_FALSE(fs::exists(directory_ / "out.exr"));
}

// A rank that throws while the others wait for it prints its error with its
// rank and ends the job.
TEST_F(Distributed, ARankThatFailsWhileRenderingEndsTheJob) {
  std::string scene = "\"" + (kScenes / "cornell-box/cornell-box.json").string() + "\" --resolution 32x32 --spp 2 --threads 1 -q";
  Result job = render(2, scene + " -o \"" + (directory_ / "out").string() + "\"", "SAFEGI_RENDER_TEST_FAULT=throw:1");
  expect_failed_without_hanging(job);
  EXPECT_NE(job.err.find("error: rank 1 of 2: test fault: rank 1 throws while rendering\n"), std::string::npos)
      << job.err;
  EXPECT_FALSE(fs::exists(directory_ / "out.exr"));
}

// A rank killed in the middle of a time-budgeted render (test hook: SIGKILL
// at its first pass): mpirun ends the job and names the rank; no hang.
TEST_F(Distributed, ARankThatDiesEndsTheJobNamingIt) {
  std::string scene = "\"" + (kScenes / "cornell-box/cornell-box.json").string() + "\" --resolution 32x32 --threads 1 -q";
  Result job = render(3, scene + " --time-budget 20 -o \"" + (directory_ / "out").string() + "\"",
                      "SAFEGI_RENDER_TEST_FAULT=kill:1");
  expect_failed_without_hanging(job);
  // Well before the 20 s budget would have ended the render.
  EXPECT_LT(job.seconds, 15.0);
  EXPECT_NE(job.err.find("test fault: rank 1 kills itself while rendering"), std::string::npos) << job.err;
  EXPECT_TRUE(std::regex_search(job.err, std::regex("rank 1 .*exited on signal 9"))) << job.err;
  EXPECT_FALSE(fs::exists(directory_ / "out.exr"));
}

}  // namespace
}  // namespace safegi::render
