// pbrt-v3's cameras as the importer reads them (src/cameras/orthographic.cpp,
// environment.cpp, perspective.cpp; CameraBase in src/core/camera.cpp): an
// orthographic view spans the screen window in camera units, [-1, 1] across the
// shorter axis by default; an environment camera reads no lens, window or
// aspect; a uniformly scaled window is a wider view, any other is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "pbrt/pbrt_import_test_support.hpp"

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

// A camera transform as an exporter writes it: `Transform` with world → camera
// (a rotation about y by 30° after one about x by 20°, the eye at (1, 2, 3)),
// each number rounded to `digits` significant digits.
std::string rounded_camera_transform(int digits) {
  const double a = 30 * std::numbers::pi / 180, b = 20 * std::numbers::pi / 180;
  // camera → world: Ry(a) Rx(b), by rows.
  const double r[3][3] = {{std::cos(a), std::sin(a) * std::sin(b), std::sin(a) * std::cos(b)},
                          {0, std::cos(b), -std::sin(b)},
                          {-std::sin(a), std::cos(a) * std::sin(b), std::cos(a) * std::cos(b)}};
  const double eye[3] = {1, 2, 3};
  std::ostringstream text;
  text << std::setprecision(digits) << "Transform [";
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row) {
      // world → camera = [Rᵀ | −Rᵀ eye], column by column as pbrt-v3 reads it.
      double value = row == 3 ? (column == 3 ? 1 : 0) : 0;
      if (row < 3 && column < 3) value = r[column][row];
      if (row < 3 && column == 3)
        value = -(r[0][row] * eye[0] + r[1][row] * eye[1] + r[2][row] * eye[2]);
      text << " " << value;
    }
  text << " ]\n";
  return text.str();
}

glm::dvec3 direction(const Camera& camera) {
  return glm::normalize(glm::dvec3(sg::raw(camera.look_at)) - glm::dvec3(sg::raw(camera.position)));
}

TEST(PbrtImportCamera, ARotationRoundedByAnExporterIsReorthonormalisedWithAWarning) {
  const PbrtScene exact = import(kFilm + rounded_camera_transform(17) + "Camera \"perspective\"\n" + world(""));
  EXPECT_EQ(exact.warnings, "");
  // Houdini's 4 significant digits: a rotation off by ~1e-4, which pbrt-v3 renders.
  const PbrtScene rounded = import(kFilm + rounded_camera_transform(4) + "Camera \"perspective\"\n" + world(""));
  EXPECT_EQ(first_line(rounded.warnings),
            "scene.pbrt:3:1: warning: the camera transform is a rotation only to within 5.3e-05: rendered with the "
            "nearest rotation");
  // The nearest rotation: the camera looks where the exact one does, to the rounding.
  const Camera &e = exact.scene.camera, &r = rounded.scene.camera;
  EXPECT_LT(glm::length(glm::dvec3(sg::raw(r.position)) - glm::dvec3(sg::raw(e.position))), 1e-3);
  EXPECT_LT(glm::length(direction(r) - direction(e)), 2e-4);
  EXPECT_LT(glm::length(glm::dvec3(sg::raw(r.up)) - glm::dvec3(sg::raw(e.up))), 2e-4);
  EXPECT_NEAR(glm::length(glm::dvec3(sg::raw(r.up))), 1.0, 1e-6);
  // 3 significant digits are still a rotation, rounded.
  const PbrtScene three = import(kFilm + rounded_camera_transform(3) + "Camera \"perspective\"\n" + world(""));
  EXPECT_NE(three.warnings.find("warning: the camera transform is a rotation only to within"), std::string::npos);
  EXPECT_LT(glm::length(direction(three.scene.camera) - direction(e)), 2e-3);
}

TEST(PbrtImportCamera, ACameraThatShearsOrScalesUnevenlyIsRefused) {
  EXPECT_EQ(first_line(import_error(kFilm + std::string("Scale 1 1.5 1\nCamera \"perspective\"\n") + world(""))),
            "scene.pbrt:3:1: error: the camera transform scales unevenly or shears (off a rotation by 0.45)");
  // 2 significant digits are no rounding the camera can take.
  EXPECT_NE(import_error(kFilm + std::string("ConcatTransform [1 0 0 0  0.05 1 0 0  0 0 1 0  0 0 0 1]\n") +
                         "Camera \"perspective\"\n" + world(""))
                .find("error: the camera transform scales unevenly or shears (off a rotation by 0.05)"),
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
