// safegi-render's command line and its refusals, run as a program: exit
// statuses (0 done, 1 the scene or the machine says no, 2 the command line
// is wrong), the one image-size limit, the memory estimate against an
// overridden machine memory (SAFEGI_RENDER_MEMORY_LIMIT), an allocation that
// fails anyway, and input bytes that must not reach the terminal raw.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <utility>

namespace safegi::render {
namespace {

namespace fs = std::filesystem;

class RenderCli : public ::testing::Test {
 protected:
  void SetUp() override { fs::create_directories(directory); }
  void TearDown() override { fs::remove_all(directory); }

  fs::path write(const std::string& name, const std::string& text) {
    fs::path file = directory / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

  // Exit status and stderr of `environment safegi-render arguments -q -o out`.
  std::pair<int, std::string> run(const std::string& arguments, const std::string& environment = "") {
    fs::path err = directory / "err.txt";
    std::string command = environment + " " + SAFEGI_RENDER_CHECKED + " " + arguments + " -q -o \"" +
                          (directory / "out").string() + "\" 2> \"" + err.string() + "\"";
    int status = std::system(command.c_str());
    std::ifstream in(err, std::ios::binary);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1,
            std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>())};
  }

  fs::path directory = fs::temp_directory_path() / ("safegi-render-cli-" + std::to_string(::getpid()));
  const std::string sphere_scene = R"({"camera": {"position": ["0 m", "0 m", "5 m"], "look_at": ["0 m", "0 m", "0 m"],
                "up": [0, 1, 0], "fov": "40 deg"},
    "shapes": [{"type": "sphere", "center": ["0 m", "0 m", "0 m"], "radius": "1 m", "material": "white"}],
    "materials": {"white": {"type": "lambert", "reflectance": [0.5, 0.5, 0.5]}},
    "lights": [{"type": "point", "position": ["0 m", "3 m", "3 m"], "intensity": "10 W/sr"}]})";
};

TEST_F(RenderCli, CommandLineErrorsExitTwoSceneErrorsOne) {
  fs::path scene = write("s.json", sphere_scene);
  EXPECT_EQ(run("\"" + scene.string() + "\" --spp 0"),
            std::make_pair(2, std::string("safegi-render: error: --spp: Value 0 not in range 1 to 16777216\n"
                                          "Run with --help for usage.\n")));
  EXPECT_EQ(run("\"" + scene.string() + "\" --no-such-option"),
            std::make_pair(2, std::string("safegi-render: error: The following argument was not expected: "
                                          "--no-such-option\nRun with --help for usage.\n")));
  EXPECT_EQ(run("\"" + scene.string() + "\" --crop 0,0,1000,1 --resolution 8x8"),
            std::make_pair(2, std::string("error: --crop: the window must be non-empty and inside the image\n")));
  EXPECT_EQ(run("\"" + scene.string() + "\" --length-unit m"),
            std::make_pair(2, std::string("error: --length-unit: only for pbrt scenes (JSON scenes carry units)\n")));
  fs::path bad = write("bad.json", R"({"camera": {"position": "1 W"}})");
  EXPECT_EQ(run("\"" + bad.string() + "\""),
            std::make_pair(1, "error: " + bad.string() + ": camera.position: expected 3 components of length (e.g. m), "
                              "got \"1 W\"\n"));
}

TEST_F(RenderCli, OneImageSizeLimitNamedInTheMessage) {
  fs::path scene = write("s.json", sphere_scene);
  EXPECT_EQ(run("\"" + scene.string() + "\" --resolution 100000x10"),
            std::make_pair(2, std::string("error: --resolution: 100000x10: the width must be 1 to 65536 pixels, "
                                          "got 100000\n")));
  EXPECT_EQ(run("\"" + scene.string() + "\" --resolution 10x0"),
            std::make_pair(2, std::string("error: --resolution: 10x0: the height must be 1 to 65536 pixels, got 0\n")));
  EXPECT_EQ(run("\"" + scene.string() + "\" --resolution 64by64"),
            std::make_pair(2, std::string("error: --resolution: expected WIDTHxHEIGHT in pixels (e.g. 640x480), "
                                          "got '64by64'\n")));
  // The scene file's limit is the same one.
  fs::path wide = write("wide.json", R"({"render": {"resolution": [100000, 10]}})");
  std::pair<int, std::string> from_file = run("\"" + wide.string() + "\"");
  EXPECT_EQ(from_file.first, 1);
  EXPECT_NE(from_file.second.find("65536"), std::string::npos) << from_file.second;
}

TEST_F(RenderCli, ARenderThatDoesNotFitIsRefusedBeforeItAllocates) {
  fs::path scene = write("s.json", sphere_scene);
  EXPECT_EQ(run("\"" + scene.string() + "\" --resolution 20000x20000 --threads 2", "SAFEGI_RENDER_MEMORY_LIMIT=8GiB"),
            std::make_pair(1, std::string("error: this render needs about 13.4 GiB of memory, more than 80 % of the "
                                          "8.0 GiB available (SAFEGI_RENDER_MEMORY_LIMIT): the 20000x20000 image "
                                          "13.4 GiB, geometry and BVH 220 B (0 triangles, 1 spheres), 2 threads "
                                          "24.3 MiB; lower --resolution, render a --crop window\n")));
  EXPECT_EQ(run("\"" + scene.string() + "\" --resolution 64x64 --threads 1 --integrator photon --photons 1000000",
                "SAFEGI_RENDER_MEMORY_LIMIT=1MiB"),
            std::make_pair(1, std::string("error: this render needs about 54.8 MiB of memory, more than 80 % of the "
                                          "1.0 MiB available (SAFEGI_RENDER_MEMORY_LIMIT): the 64x64 image 144.0 KiB, "
                                          "geometry and BVH 220 B (0 triangles, 1 spheres), 1 thread 256.2 KiB, "
                                          "photons 54.4 MiB; lower --resolution, render a --crop window or trace "
                                          "fewer --photons\n")));
  // A pixel filter keeps each pixel's weight sum too (8 B more a pixel); the
  // spatial light choice, a table per voxel (64³ slots, a distribution of two lights in each).
  std::string filtered = sphere_scene;
  auto replace = [&](std::string_view from, std::string_view to) { filtered.replace(filtered.find(from), from.size(), to); };
  replace(R"({"camera")", R"({"render": {"filter": {"type": "gaussian"}, "light_strategy": "spatial"}, "camera")");
  replace(R"("intensity": "10 W/sr"})",
          R"("intensity": "10 W/sr"}, {"type": "point", "position": ["0 m", "3 m", "-3 m"], "intensity": "1 W/sr"})");
  EXPECT_EQ(run("\"" + write("f.json", filtered).string() + "\" --resolution 20000x20000 --threads 2",
                "SAFEGI_RENDER_MEMORY_LIMIT=8GiB"),
            std::make_pair(1, std::string("error: this render needs about 16.4 GiB of memory, more than 80 % of the "
                                          "8.0 GiB available (SAFEGI_RENDER_MEMORY_LIMIT): the 20000x20000 image "
                                          "16.4 GiB, geometry and BVH 220 B (0 triangles, 1 spheres), 2 threads "
                                          "24.3 MiB, light choice 4.0 MiB; lower --resolution, render a --crop window\n")));
  // A crop window is what is allocated.
  EXPECT_EQ(run("\"" + scene.string() + "\" --resolution 20000x20000 --crop 0,0,32,32 --spp 1 --threads 1",
                "SAFEGI_RENDER_MEMORY_LIMIT=8GiB")
                .first,
            0);
  EXPECT_EQ(run("\"" + scene.string() + "\"", "SAFEGI_RENDER_MEMORY_LIMIT=lots"),
            std::make_pair(1, std::string("error: SAFEGI_RENDER_MEMORY_LIMIT: expected bytes, or a number with KiB, "
                                          "MiB, GiB or TiB, got 'lots'\n")));
}

TEST_F(RenderCli, AnAllocationThatFailsAnywayIsSaidInWords) {
  // The estimate is told of a machine far larger than the address space the
  // shell allows (4 GiB), so the film's allocation itself fails.
  fs::path scene = write("s.json", sphere_scene);
  EXPECT_EQ(run("\"" + scene.string() + "\" --resolution 60000x60000 --threads 1",
                "ulimit -v 4194304; SAFEGI_RENDER_MEMORY_LIMIT=1TiB"),
            std::make_pair(1, std::string("error: out of memory while rendering: an allocation failed (std::bad_alloc); "
                                          "1.0 TiB available (SAFEGI_RENDER_MEMORY_LIMIT)\n")));
}

TEST_F(RenderCli, ControlBytesInAPbrtFileAreEscapedAndTheDiagnosticIsWhole) {
  using namespace std::string_literals;
  // A NUL once cut the diagnostic short, and the rest was printed as a plain
  // message: "error: garbage.pbrt:1:1: error: ...".
  fs::path scene = write("garbage.pbrt", "WorldBegin\n\x1b[2J\0 \x9b\n"s);
  EXPECT_EQ(run("\"" + scene.string() + "\" --length-unit m"),
            std::make_pair(1, scene.string() + ":2:1: error: unknown directive '\\x1B'\n"
                                               "\\x1B[2J\\x00 \\x9B\n"
                                               "^~~~\n"));
}

}  // namespace
}  // namespace safegi::render
