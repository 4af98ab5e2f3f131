// pbrt-v3's cameras as the importer reads them (src/cameras/orthographic.cpp,
// environment.cpp, perspective.cpp; CameraBase in src/core/camera.cpp): an
// orthographic view spans the screen window in camera units, [-1, 1] across the
// shorter axis by default; an environment camera reads no lens, window or
// aspect; a uniformly scaled window is a wider view, any other is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pbrt_import_test_support.hpp"

namespace safegi::render {
namespace {

using namespace pbrt_test;

constexpr const char* kFilm = "Film \"image\" \"integer xresolution\" 200 \"integer yresolution\" 100\n";

TEST(PbrtImportCamera, OrthographicSpansTheScreenWindowInCameraUnits) {
  const std::string look = "LookAt 0 0 -10 0 0 0 0 1 0\n";
  PbrtScene plain = import(kFilm + look + "Camera \"orthographic\"\n" + world(""), in_memory({}, 0.01));
  const Camera& c = plain.scene.camera;
  EXPECT_EQ(c.projection, CameraProjection::orthographic);
  EXPECT_NEAR(sg::raw(c.view_size), 0.02f, 1e-8);  // [-1, 1] pbrt units of 1 cm, across the shorter axis
  // A camera transform that scales by 2 makes a camera unit 2 world units.
  PbrtScene scaled = import(kFilm + std::string("Scale 0.5 0.5 0.5\n") + look + "Camera \"orthographic\"\n" + world(""),
                            in_memory({}, 0.01));
  EXPECT_NEAR(sg::raw(scaled.scene.camera.view_size), 0.04f, 1e-8);
  PbrtScene window = import(kFilm + look + "Camera \"orthographic\" \"float screenwindow\" [-10 10 -5 5]\n" + world(""));
  EXPECT_NEAR(sg::raw(window.scene.camera.view_size), 10.0f, 1e-5);
  EXPECT_EQ(window.warnings, "");
}

TEST(PbrtImportCamera, AScaledScreenWindowWidensThePerspectiveView) {
  PbrtScene scene = import(kFilm + std::string("Camera \"perspective\" \"float fov\" 90 \"float screenwindow\" [-4 4 -2 2]\n") +
                           world(""));
  // tan(fov'/2) = 2 tan(45°)
  EXPECT_NEAR(sg::raw(scene.scene.camera.fov), 2 * std::atan(2.0), 1e-6);
}

TEST(PbrtImportCamera, ScreenWindowsThatShiftOrStretchAreRefused) {
  EXPECT_EQ(first_line(import_error(kFilm + std::string("Camera \"orthographic\" \"float screenwindow\" [-1 3 -1 1]\n") +
                                    world(""))),
            "scene.pbrt:2:23: error: only a \"screenwindow\" centred on the view with the film's aspect is supported");
  EXPECT_NE(import_error(kFilm + std::string("Camera \"perspective\" \"float screenwindow\" [-2 2 -2 2]\n") + world(""))
                .find("help: expected [-2s 2s -1s 1s] for some s > 0"),
            std::string::npos);
}

TEST(PbrtImportCamera, EnvironmentSeesEveryDirectionAndReadsNoLens) {
  PbrtScene scene = import(kFilm + std::string("LookAt 0 0 0 0 0 1 0 1 0\nCamera \"environment\" \"float lensradius\" 1\n") +
                           world(""));
  EXPECT_EQ(scene.scene.camera.projection, CameraProjection::environment);
  EXPECT_EQ(sg::raw(scene.scene.camera.lens_radius), 0.0f);
  EXPECT_NE(scene.warnings.find("parameter \"float lensradius\" of Camera \"environment\" is not used"),
            std::string::npos);
}

TEST(PbrtImportCamera, RealisticIsRefusedNamingTheSupportedOnes) {
  EXPECT_EQ(import_error("Camera \"realistic\" \"string lensfile\" \"wide.dat\"\n" + world("")),
            "scene.pbrt:1:8: error: camera \"realistic\" is not supported\n"
            "Camera \"realistic\" \"string lensfile\" \"wide.dat\"\n"
            "       ^~~~~~~~~~~\n"
            "help: supported: \"perspective\", \"orthographic\", \"environment\"\n");
}

}  // namespace
}  // namespace safegi::render
