// The pbrt-v3 reader: tokens, directive grammar, diagnostics (exact text),
// the mapping into Scene (camera, handedness, units, materials, lights,
// shapes, instances, Include), and that no input crashes it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include "pbrt/pbrt_import_test_support.hpp"
#include "pbrt/pbrt_tokenizer.hpp"

namespace safegi::render {
namespace {

using namespace pbrt_test;

std::vector<std::string> tokens(const std::string& text) {
  SourceManager sources;
  FileId file = sources.add_file("t.pbrt", text);
  pbrt::Tokenizer tokenizer(sources, file);
  std::vector<std::string> result;
  for (pbrt::Token t = tokenizer.next(); t.kind != pbrt::TokenKind::end; t = tokenizer.next())
    result.push_back(pbrt::describe(t));
  return result;
}

glm::vec3 raw(const PointWorld& p) { return sg::raw(p); }

// ---------------------------------------------------------------------------
// Tokens and grammar

TEST(PbrtTokenizer, TokenClassesAsPbrtV3) {
  EXPECT_EQ(tokens("Shape \"sphere\" [1 -2.5e3]# comment\n\"a\\\"b\\n\"x[y]"),
            (std::vector<std::string>{"'Shape'", "the string \"sphere\"", "'['", "'1'", "'-2.5e3'", "']'",
                                      "the string \"a\"b\\x0A\"", "'x'", "'['", "'y'", "']'"}));
  EXPECT_EQ(tokens("# only a comment"), std::vector<std::string>{});
  EXPECT_EQ(tokens("1#not-a-comment"), std::vector<std::string>{"'1#not-a-comment'"});
}

TEST(PbrtTokenizer, BrokenStringsAreErrors) {
  EXPECT_EQ(import_error("Film \"image\" \"string filename\" \"x.exr\nWorldBegin"),
            "scene.pbrt:1:32: error: unterminated string: expected '\"' before the end of the line\n"
            "Film \"image\" \"string filename\" \"x.exr\n"
            "                               ^\n"
            "help: pbrt-v3 strings end on the line they start on\n");
  EXPECT_EQ(import_error("Film \"a\\q\""),
            "scene.pbrt:1:8: error: unknown escape '\\q' in a string\n"
            "Film \"a\\q\"\n"
            "       ^~\n"
            "help: pbrt-v3 knows \\b \\f \\n \\r \\t \\\\ \\' \\\"\n");
}

TEST(PbrtParser, DirectiveErrorsNameWhatWasExpected) {
  EXPECT_EQ(import_error("Shpe \"sphere\""),
            "scene.pbrt:1:1: error: unknown directive 'Shpe'\nShpe \"sphere\"\n^~~~\nhelp: did you mean 'Shape'?\n");
  EXPECT_EQ(import_error("ColorSpace \"srgb\""),
            "scene.pbrt:1:1: error: unknown directive 'ColorSpace'\nColorSpace \"srgb\"\n^~~~~~~~~~\n"
            "help: ColorSpace is pbrt-v4 syntax; this reader takes pbrt-v3 scenes\n");
  EXPECT_EQ(import_error("LookAt 0 0 0 0 0 1\nWorldBegin"),
            "scene.pbrt:2:1: error: expected a number (LookAt takes 9, this is number 7), found 'WorldBegin'\n"
            "WorldBegin\n^~~~~~~~~~\n");
  EXPECT_EQ(import_error("Translate 1 2 x3"),
            "scene.pbrt:1:15: error: expected a number (Translate takes 3, this is number 3), found 'x3'\n"
            "Translate 1 2 x3\n              ^~\n");
  EXPECT_EQ(import_error("Translate 1 2 3e999"),
            "scene.pbrt:1:15: error: number '3e999' is out of range\nTranslate 1 2 3e999\n              ^~~~~\n");
  EXPECT_EQ(import_error("Transform 1 0 0 0"),
            "scene.pbrt:1:11: error: expected '[' after Transform, found '1'\nTransform 1 0 0 0\n          ^\n"
            "help: Transform takes [ 16 numbers ], the matrix column by column\n");
  EXPECT_EQ(import_error("Shape sphere"),
            "scene.pbrt:1:7: error: expected a type name (a quoted string) after Shape, found 'sphere'\n"
            "Shape sphere\n      ^~~~~~\n");
  EXPECT_EQ(import_error("\"float radius\" [1]"),
            "scene.pbrt:1:1: error: expected a directive (Shape, Material, Translate, ...), found the string "
            "\"float radius\"\n\"float radius\" [1]\n^~~~~~~~~~~~~~\n"
            "help: a parameter list follows a directive and its quoted name, e.g. Shape \"sphere\" \"float radius\" [1]\n");
}

TEST(PbrtParser, ParameterListErrors) {
  EXPECT_EQ(import_error(world("Shape \"sphere\" \"flaot radius\" 1")),
            "scene.pbrt:2:16: error: unknown parameter type 'flaot' in the string \"flaot radius\"\n"
            "Shape \"sphere\" \"flaot radius\" 1\n               ^~~~~~~~~~~~~~\n"
            "help: did you mean \"float radius\"?\n");
  EXPECT_EQ(import_error(world("Shape \"sphere\" \"radius\" 1")),
            "scene.pbrt:2:16: error: expected a parameter declaration \"type name\" (e.g. \"float radius\"), found the "
            "string \"radius\"\nShape \"sphere\" \"radius\" 1\n               ^~~~~~~~\n");
  EXPECT_EQ(import_error("WorldBegin\nShape \"sphere\" \"float radius\" [1"),
            "scene.pbrt:2:31: error: the list of \"float radius\" is not closed: the file ends before its ']'\n"
            "Shape \"sphere\" \"float radius\" [1\n                              ^\n");
  EXPECT_EQ(import_error(world("Shape \"sphere\" \"float radius\" [1 \"2\"]")),
            "scene.pbrt:2:34: error: the list of \"float radius\" mixes numbers and strings\n"
            "Shape \"sphere\" \"float radius\" [1 \"2\"]\n                                 ^~~\n");
  EXPECT_EQ(import_error(world("AreaLightSource \"diffuse\" \"bool twosided\" \"yes\"")),
            "scene.pbrt:2:43: error: expected \"true\" or \"false\" for \"bool twosided\", found the string \"yes\"\n"
            "AreaLightSource \"diffuse\" \"bool twosided\" \"yes\"\n"
            "                                          ^~~~~\n");
  EXPECT_EQ(import_error(world("Shape \"sphere\" \"integer radius\" [2]")),
            "scene.pbrt:2:16: error: Shape \"sphere\" reads \"radius\" as \"float\", found \"integer radius\"\n"
            "Shape \"sphere\" \"integer radius\" [2]\n               ^~~~~~~~~~~~~~~~\n"
            "help: pbrt-v3 would ignore this parameter and use its default; write the type it expects\n");
  EXPECT_EQ(import_error(world("Shape \"sphere\" \"float radius\" [1 2]")),
            "scene.pbrt:2:31: error: \"float radius\" of Shape \"sphere\" takes 1 value, found 2\n"
            "Shape \"sphere\" \"float radius\" [1 2]\n                              ^~~~~\n");
}

// ---------------------------------------------------------------------------
// Structure and what is not supported

TEST(PbrtImport, StructureErrors) {
  EXPECT_EQ(import_error("WorldBegin\nShape \"sphere\""),
            "scene.pbrt:2:1: error: the scene ends before WorldEnd\nShape \"sphere\"\n^~~~~\n"
            "help: a truncated file? pbrt-v3 renders at WorldEnd\n");
  EXPECT_EQ(import_error("Shape \"sphere\""),
            "scene.pbrt:1:1: error: Shape must come between WorldBegin and WorldEnd\nShape \"sphere\"\n^~~~~\n"
            "help: pbrt-v3 describes the scene in the world block\n");
  EXPECT_EQ(import_error(world("Camera \"perspective\"")),
            "scene.pbrt:2:1: error: Camera must come before WorldBegin\nCamera \"perspective\"\n^~~~~~\n"
            "help: pbrt-v3 sets render options only outside the world block\n");
  EXPECT_EQ(import_error(world("AttributeEnd")),
            "scene.pbrt:2:1: error: AttributeEnd without a matching AttributeBegin\nAttributeEnd\n^~~~~~~~~~~~\n");
  EXPECT_EQ(import_error(world("") + "Shape \"sphere\""),
            "scene.pbrt:4:1: error: directive after WorldEnd\nShape \"sphere\"\n^~~~~\n"
            "help: a scene file renders one image: one WorldBegin ... WorldEnd block\n");
  EXPECT_EQ(import_error(world("NamedMaterial \"gold\"")),
            "scene.pbrt:2:15: error: no material named \"gold\"\nNamedMaterial \"gold\"\n              ^~~~~~\n"
            "help: MakeNamedMaterial defines one\n");
}

TEST(PbrtImport, UnsupportedFeaturesAreNamed) {
  EXPECT_EQ(import_error(world("Shape \"bilinearmesh\"")),
            "scene.pbrt:2:7: error: shape \"bilinearmesh\" is not supported\nShape \"bilinearmesh\"\n      ^~~~~~~~~~~~~~\n"
            "help: supported: \"trianglemesh\", \"plymesh\", \"sphere\", \"disk\", \"cylinder\", \"cone\", "
            "\"paraboloid\", \"hyperboloid\", \"nurbs\", \"heightfield\", \"loopsubdiv\", \"curve\"\n");
  EXPECT_EQ(import_error(world(used("Material \"hair\""))),
            "scene.pbrt:2:10: error: material \"hair\" is not supported\nMaterial \"hair\"\n"
            "         ^~~~~~\nhelp: supported: \"matte\", \"mirror\", \"plastic\", \"glass\", \"metal\", \"substrate\", "
            "\"translucent\", \"uber\", \"mix\", \"disney\"\n");
  // pbrt-v3's matte with "sigma" (degrees) is Oren-Nayar; 0 is Lambert.
  PbrtScene rough = import(world(used("Material \"matte\" \"float sigma\" [20] \"rgb Kd\" [0.4 0.5 0.6]")));
  const OrenNayarMaterial oren_nayar = as<OrenNayarMaterial>(rough.scene.materials.at(rough.scene.shapes[0].material));
  const double s2 = std::pow(20 * std::numbers::pi / 180, 2);
  EXPECT_NEAR(oren_nayar.a, 1 - s2 / (2 * (s2 + 0.33)), 1e-6);
  EXPECT_NEAR(oren_nayar.b, 0.45 * s2 / (s2 + 0.09), 1e-6);
  EXPECT_EQ(sg::raw(oren_nayar.diffuse.value), glm::vec3(0.4f, 0.5f, 0.6f));
  PbrtScene smooth = import(world(used("Material \"matte\" \"float sigma\" [0]")));
  EXPECT_TRUE(is<LambertMaterial>(smooth.scene.materials.at(smooth.scene.shapes[0].material)));
  EXPECT_EQ(first_line(import_error(world(used("Material \"matte\" \"float sigma\" [-5]")))),
            "scene.pbrt:2:10: error: \"sigma\" of Material \"matte\" must lie in [0, 90] degrees, found -5");
  EXPECT_EQ(import_error(world("LightSource \"laser\"")),
            "scene.pbrt:2:13: error: light \"laser\" is not supported\nLightSource \"laser\"\n"
            "            ^~~~~~~\nhelp: supported: \"point\", \"spot\", \"goniometric\", \"projection\", \"distant\", "
            "\"infinite\"\n");
  EXPECT_EQ(import_error(world(used_texture("Texture \"t\" \"spectrum\" \"ptex\""))),
            "scene.pbrt:2:24: error: texture \"ptex\" is not supported\n"
            "Texture \"t\" \"spectrum\" \"ptex\"\n"
            "                       ^~~~~~\nhelp: supported: \"constant\", \"imagemap\", \"scale\", \"mix\", \"checkerboard\", "
            "\"dots\", \"fbm\", \"wrinkled\", \"windy\", \"marble\", \"uv\", \"bilerp\"\n");
  EXPECT_EQ(import_error("Integrator \"ambientocclusion\"\n" + world("")),
            "scene.pbrt:1:12: error: integrator \"ambientocclusion\" is not supported\nIntegrator \"ambientocclusion\"\n"
            "           ^~~~~~~~~~~~~~~~~~\n"
            "help: supported: \"path\", \"volpath\", \"bdpt\", \"sppm\", \"directlighting\", \"whitted\" (as "
            "direct lighting); \"mlt\" (as bdpt)\n");
  EXPECT_EQ(import_error("ActiveTransform EndTime\nTranslate 1 0 0\nCamera \"perspective\"\n" + world("")),
            "scene.pbrt:3:1: error: an animated camera (a transform ActiveTransform changed at one time only) is not "
            "supported\nCamera \"perspective\"\n^~~~~~\n"
            "help: animate the objects instead: their motion blurs as pbrt-v3's does\n");
  EXPECT_EQ(import_error(world(used("Material \"matte\" \"rgb Kd\" [1.5 0 0]"))),
            "scene.pbrt:2:18: error: \"Kd\" of Material \"matte\" must lie in [0, 1] in every channel\n"
            "Material \"matte\" \"rgb Kd\" [1.5 0 0]\n                 ^~~~~~~~\n"
            "help: above 1 a surface reflects more light than it receives\n");
}

TEST(PbrtImport, IgnoredParametersAreWarnings) {
  PbrtScene scene = import(world("Shape \"sphere\" \"float radius\" 1 \"float raduis\" 2"));
  EXPECT_EQ(scene.warnings,
            "scene.pbrt:2:33: warning: parameter \"float raduis\" of Shape \"sphere\" is not used\n"
            "Shape \"sphere\" \"float radius\" 1 \"float raduis\" 2\n                                ^~~~~~~~~~~~~~\n"
            "help: pbrt-v3 ignores it too (misspelt?)\n");
}

TEST(PbrtImport, PixelFiltersArePbrtV3sWithItsDefaults) {
  auto filter_of = [](const std::string& directive) {
    PbrtScene scene = import(directive + "\n" + world(""));
    EXPECT_EQ(scene.warnings, "") << directive;
    return scene.scene.settings.filter;
  };
  PixelFilter box = filter_of("");
  EXPECT_EQ(box.type, PixelFilterType::box);
  EXPECT_EQ(box.radius_x, 0.5);
  PixelFilter gaussian = filter_of("PixelFilter \"gaussian\"");
  EXPECT_EQ(gaussian.type, PixelFilterType::gaussian);
  EXPECT_EQ(gaussian.radius_x, 2);
  EXPECT_EQ(gaussian.radius_y, 2);
  EXPECT_EQ(gaussian.gaussian_alpha, 2);
  EXPECT_EQ(gaussian.mode, PixelFilterMode::splat);  // pbrt-v3's Film::AddSample
  PixelFilter mitchell = filter_of("PixelFilter \"mitchell\" \"float xwidth\" 1.5 \"float B\" 0.5 \"float C\" 0.25");
  EXPECT_EQ(mitchell.type, PixelFilterType::mitchell);
  EXPECT_EQ(mitchell.radius_x, 1.5);
  EXPECT_EQ(mitchell.radius_y, 2);
  EXPECT_EQ(mitchell.mitchell_b, 0.5);
  EXPECT_EQ(mitchell.mitchell_c, 0.25);
  PixelFilter sinc = filter_of("PixelFilter \"sinc\" \"float tau\" 2");
  EXPECT_EQ(sinc.radius_x, 4);
  EXPECT_EQ(sinc.sinc_tau, 2);
  EXPECT_EQ(filter_of("PixelFilter \"triangle\"").type, PixelFilterType::triangle);
  EXPECT_EQ(import_error("PixelFilter \"lanczos\"\n" + world("")),
            "scene.pbrt:1:13: error: unknown pixel filter \"lanczos\"\nPixelFilter \"lanczos\"\n            ^~~~~~~~~\n"
            "help: expected \"box\", \"triangle\", \"gaussian\", \"mitchell\" or \"sinc\" (pbrt-v3's five)\n");
  EXPECT_EQ(import_error("PixelFilter \"box\" \"float xwidth\" 0\n" + world("")),
            "scene.pbrt:1:19: error: a filter's \"float xwidth\" must be 0.001 to 64 pixels\n"
            "PixelFilter \"box\" \"float xwidth\" 0\n                  ^~~~~~~~~~~~~~\n");
  EXPECT_EQ(first_line(import_error("PixelFilter \"gaussian\" \"float alpha\" -1\n" + world(""))),
            "scene.pbrt:1:24: error: a filter's \"float alpha\" must be in (0, 1e6]");
  EXPECT_EQ(first_line(import_error("PixelFilter \"mitchell\" \"float B\" 1e30\n" + world(""))),
            "scene.pbrt:1:24: error: a filter's \"float B\" must be in (-10, 10]");
}

TEST(PbrtImport, UnitsMustBeDeclared) {
  EXPECT_EQ(import_error(world(""), in_memory({}, 0)),
            "scene.pbrt: pbrt scenes carry no units: say what one pbrt length unit is "
            "(safegi-render --length-unit m|cm|mm|...)\n");
  EXPECT_DOUBLE_EQ(parse_length_unit("cm"), 0.01);
  EXPECT_DOUBLE_EQ(parse_length_unit("mm"), 0.001);
  EXPECT_DOUBLE_EQ(parse_length_unit("in"), 0.0254);
  EXPECT_DOUBLE_EQ(parse_length_unit("0.5 m"), 0.5);
  EXPECT_THROW(parse_length_unit("W"), SceneError);
  EXPECT_THROW(parse_length_unit("-1 m"), SceneError);
  EXPECT_THROW(parse_length_unit("parsec"), SceneError);
}

// ---------------------------------------------------------------------------
// The mapping into Scene

TEST(PbrtImport, OptionsBecomeRenderSettings) {
  PbrtScene scene = import(
      "Film \"image\" \"integer xresolution\" [200] \"integer yresolution\" 100 \"float cropwindow\" [0.5 1 0 0.25]\n"
      "Sampler \"sobol\" \"integer pixelsamples\" 20\nIntegrator \"directlighting\" \"integer maxdepth\" [3]\n" + world(""));
  EXPECT_EQ(scene.scene.settings.width, 200);
  EXPECT_EQ(scene.scene.settings.height, 100);
  EXPECT_EQ(scene.scene.settings.spp, 32);  // pbrt-v3's Sobol sampler rounds up to a power of 2
  EXPECT_EQ(scene.scene.settings.integrator, IntegratorType::direct);
  EXPECT_EQ(scene.scene.settings.max_depth, 3);
  EXPECT_FALSE(scene.scene.settings.russian_roulette);  // pbrt-v3's specular chains end at maxdepth only
  ASSERT_TRUE(scene.crop);
  EXPECT_EQ(scene.crop->x, 100);
  EXPECT_EQ(scene.crop->y, 0);
  EXPECT_EQ(scene.crop->width, 100);
  EXPECT_EQ(scene.crop->height, 25);
  // pbrt-v3's defaults: 1280x720, 16 samples, path tracing to depth 5.
  PbrtScene defaults = import(world(""));
  EXPECT_EQ(defaults.scene.settings.width, 1280);
  EXPECT_EQ(defaults.scene.settings.height, 720);
  EXPECT_EQ(defaults.scene.settings.spp, 16);
  EXPECT_EQ(defaults.scene.settings.integrator, IntegratorType::path);
  EXPECT_EQ(defaults.scene.settings.max_depth, 5);
  EXPECT_EQ(import("Sampler \"stratified\" \"integer xsamples\" 3 \"integer ysamples\" 5\n" + world("")).scene.settings.spp, 15);
}

// pbrt-v3's Film multiplies the image by "scale" as it writes it.
TEST(PbrtImport, FilmScaleScalesTheImage) {
  EXPECT_EQ(import(world("")).scene.settings.film_scale, 1.0);
  PbrtScene scaled = import("Film \"image\" \"float scale\" [ 2.5 ]\n" + world(""));
  EXPECT_EQ(scaled.scene.settings.film_scale, 2.5);
  EXPECT_EQ(scaled.warnings, "");
  EXPECT_EQ(first_line(import_error("Film \"image\" \"float scale\" -1\n" + world(""))),
            "scene.pbrt:1:14: error: Film \"float scale\" must be positive and finite");
}

// pbrt-v3's camera space: x is the image's right, y up, z forward. LookAt
// makes that frame right-handed in the world, where our camera (right =
// forward × up) would mirror the image: the import mirrors the world across
// x instead, so the image stays pbrt's. With "Scale -1 1 1" first (as
// compare_pbrt.sh writes), nothing is mirrored.
TEST(PbrtImport, CameraHandednessKeepsPbrtsImage) {
  PbrtScene mirrored = import("LookAt 1 2 3  1 2 4  0 1 0\nCamera \"perspective\" \"float fov\" 45\n" +
                              world("LightSource \"point\" \"point from\" [5 6 7]"));
  const Camera& c = mirrored.scene.camera;
  EXPECT_EQ(raw(c.position), glm::vec3(-1, 2, 3));
  EXPECT_NEAR(raw(c.look_at).z, 4, 1e-6);
  EXPECT_NEAR(sg::raw(c.up).y, 1, 1e-6);
  EXPECT_NEAR(sg::raw(c.fov), 45 * std::numbers::pi / 180, 1e-6);
  EXPECT_EQ(raw(mirrored.scene.point_lights[0].position), glm::vec3(-5, 6, 7));
  // Image right, ours: forward × up = (0,0,1) × (0,1,0) = -x in our world, i.e. +x in pbrt's: its camera's x axis.
  glm::vec3 forward = glm::normalize(raw(c.look_at) - raw(c.position));
  EXPECT_NEAR(glm::cross(forward, sg::raw(c.up)).x, -1, 1e-6);

  PbrtScene straight = import("Scale -1 1 1\nLookAt 1 2 3  1 2 4  0 1 0\nCamera \"perspective\"\n" +
                              world("LightSource \"point\" \"point from\" [5 6 7]"));
  EXPECT_EQ(raw(straight.scene.camera.position), glm::vec3(1, 2, 3));
  EXPECT_EQ(raw(straight.scene.point_lights[0].position), glm::vec3(5, 6, 7));
}

TEST(PbrtImport, LengthUnitScalesLengthsAndKeepsPixelValues) {
  std::string text = "LookAt 0 0 -10 0 0 0 0 1 0\nCamera \"perspective\" \"float lensradius\" 0.5 \"float focaldistance\" 10\n" +
                     world("LightSource \"point\" \"rgb I\" [100 100 100] \"point from\" [0 10 0]\n"
                           "AreaLightSource \"diffuse\" \"rgb L\" [2 3 4]\nTranslate 1 2 3\nShape \"sphere\" \"float radius\" 2");
  PbrtScene cm = import(text, in_memory({}, 0.01));
  EXPECT_NEAR(raw(cm.scene.camera.position).z, -0.1f, 1e-7);
  EXPECT_NEAR(sg::raw(cm.scene.camera.lens_radius), 0.005f, 1e-9);
  EXPECT_NEAR(sg::raw(cm.scene.camera.focus_distance), 0.1f, 1e-8);
  EXPECT_NEAR(raw(cm.scene.point_lights[0].position).y, 0.1f, 1e-8);
  // E = I / r² must stay what pbrt computes in its own units: I × (0.01)².
  EXPECT_NEAR(sg::raw(cm.scene.point_lights[0].intensity).x, 0.01f, 1e-8);
  ASSERT_EQ(cm.scene.shapes.size(), 1u);
  EXPECT_NEAR(sg::raw(cm.scene.shapes[0].radius), 0.02f, 1e-9);
  EXPECT_NEAR(raw(cm.scene.shapes[0].render_from_object(cm.scene.shapes[0].center)).y, 0.02f, 1e-9);
  EXPECT_EQ(sg::raw(*cm.scene.shapes[0].emission), glm::vec3(2, 3, 4));  // radiance: as written
}

TEST(PbrtImport, MaterialsFollowTheGraphicsState) {
  PbrtScene scene = import(world(
      "Shape \"sphere\"\n"                                                     // default: matte 0.5
      "MakeNamedMaterial \"red\" \"string type\" \"matte\" \"rgb Kd\" [0.8 0.1 0.1]\n"
      "AttributeBegin\n  NamedMaterial \"red\"\n  Shape \"sphere\"\n"
      "  Shape \"sphere\" \"rgb Kd\" [0 0.5 0]\n"                            // the shape overrides Kd
      "  Material \"mirror\"\n  Shape \"sphere\"\nAttributeEnd\n"
      "Texture \"grey\" \"spectrum\" \"constant\" \"rgb value\" [0.3 0.3 0.3]\n"
      "Material \"matte\" \"texture Kd\" \"grey\"\nShape \"sphere\"\n"
      "Material \"matte\" \"rgb Kd\" [0 0 0]\nShape \"sphere\""));              // black: absorbs, as in pbrt
  const Scene& s = scene.scene;
  ASSERT_EQ(s.shapes.size(), 6u);
  auto material = [&](size_t shape) { return s.materials.at(s.shapes[shape].material); };
  EXPECT_TRUE(is<LambertMaterial>(material(0)));
  EXPECT_EQ(sg::raw(diffuse(material(0)).value), glm::vec3(0.5f));
  EXPECT_EQ(sg::raw(diffuse(material(1)).value), glm::vec3(0.8f, 0.1f, 0.1f));
  EXPECT_EQ(sg::raw(diffuse(material(2)).value), glm::vec3(0, 0.5f, 0));
  EXPECT_TRUE(is<MirrorMaterial>(material(3)));
  EXPECT_EQ(sg::raw(as<MirrorMaterial>(material(3)).reflectance), glm::vec3(0.9f));  // pbrt-v3's default Kr
  EXPECT_EQ(sg::raw(diffuse(material(4)).value), glm::vec3(0.3f));
  EXPECT_EQ(s.shapes[5].material, -1);
  // A named material made inside an attribute block ends with it.
  EXPECT_EQ(import_error(world("AttributeBegin\nMakeNamedMaterial \"m\" \"string type\" \"matte\"\nAttributeEnd\n"
                               "NamedMaterial \"m\"")),
            "scene.pbrt:5:15: error: no material named \"m\"\nNamedMaterial \"m\"\n              ^~~\n"
            "help: MakeNamedMaterial defines one\n");
}

TEST(PbrtImport, TriangleMeshesAreBakedInWorldMetres) {
  PbrtScene scene = import(world("Translate 0 0 5\nScale 2 2 2\n"
                                 "Shape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 1 1 0 0 1 0] \"integer indices\" [0 1 2 0 2 3]\n"
                                 "Shape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0]"),  // 3 points: no indices needed
                           in_memory({}, 0.5));
  const Scene& s = scene.scene;
  ASSERT_EQ(s.shapes.size(), 2u);
  EXPECT_EQ(s.shapes[0].indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  // pbrt world (2x, 2y, 2z + 5), mirrored across x (LookAt-less default camera), in half metres.
  EXPECT_EQ(raw(s.shapes[0].render_from_object(s.shapes[0].positions[2])), glm::vec3(-1, 1, 2.5f));
  EXPECT_EQ(s.shapes[1].indices, (std::vector<uint32_t>{0, 1, 2}));
}

// An emitter emits on the side of pbrt-v3's geometric normal: its winding's
// in pbrt's world, flipped by ReverseOrientation and by a mirroring transform,
// or the side its vertex normals point to. The mirrored import world flips
// every winding, so the importer re-winds emitters to keep pbrt's side.
TEST(PbrtImport, EmittersKeepPbrtsSide) {
  auto emitter_normal = [](const std::string& body, const std::string& camera = "") {
    PbrtScene scene = import(camera + world("AreaLightSource \"diffuse\"\n" + body));
    const Shape& shape = scene.scene.shapes.at(0);
    auto p = [&](int i) { return raw(shape.positions[shape.indices[i]]); };
    glm::vec3 n = glm::normalize(glm::cross(p(1) - p(0), p(2) - p(0)));
    return n;
  };
  const std::string quad = "Shape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 1 1 0 0 1 0] \"integer indices\" [0 1 2 0 2 3]";
  // pbrt: normal +z (right-handed winding). Default camera: world mirrored in x, z unchanged.
  EXPECT_EQ(emitter_normal(quad), glm::vec3(0, 0, 1));
  EXPECT_EQ(emitter_normal(quad, "Scale -1 1 1\n"), glm::vec3(0, 0, 1));
  EXPECT_EQ(emitter_normal("ReverseOrientation\n" + quad), glm::vec3(0, 0, -1));
  EXPECT_EQ(emitter_normal("Scale 1 1 -1\n" + quad), glm::vec3(0, 0, -1));  // a mirroring transform flips
  EXPECT_EQ(emitter_normal("Scale 1 -1 1\n" + quad), glm::vec3(0, 0, 1));  // mirrored object: pbrt flips back
  EXPECT_EQ(emitter_normal("Shape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 1 1 0] \"normal N\" [0 0 -1 0 0 -1 0 0 -1]"),
            glm::vec3(0, 0, -1));
}

TEST(PbrtImport, LightsAsPbrtV3DefinesThem) {
  PbrtScene scene = import(
      "Scale -1 1 1\nCamera \"perspective\"\n" +
      world("Translate 1 0 0\n"
            "LightSource \"point\" \"rgb I\" [1 2 3] \"rgb scale\" [2 2 2] \"point from\" [0 5 0]\n"
            "Rotate 90 0 0 1\n"
            "LightSource \"spot\" \"point from\" [0 0 0] \"point to\" [1 0 0] \"float coneangle\" 40 "
            "\"float conedeltaangle\" 10\n"));
  const Scene& s = scene.scene;
  ASSERT_EQ(s.point_lights.size(), 1u);
  EXPECT_EQ(raw(s.point_lights[0].position), glm::vec3(1, 5, 0));  // pbrt-v3 offsets "from" in world space
  EXPECT_EQ(sg::raw(s.point_lights[0].intensity), glm::vec3(2, 4, 6));
  ASSERT_EQ(s.spot_lights.size(), 1u);
  const SpotLight& spot = s.spot_lights[0];
  EXPECT_EQ(raw(spot.position), glm::vec3(1, 0, 0));
  EXPECT_NEAR(sg::raw(spot.direction).y, 1, 1e-6);  // +x rotated 90° about z
  EXPECT_NEAR(sg::raw(spot.cone_angle), 40 * std::numbers::pi / 180, 1e-6);
  EXPECT_NEAR(sg::raw(spot.cone_delta), 10 * std::numbers::pi / 180, 1e-6);
  EXPECT_EQ(sg::raw(spot.intensity), glm::vec3(1));
  EXPECT_EQ(import_error(world("LightSource \"spot\" \"float coneangle\" 10 \"float conedeltaangle\" 20")),
            "scene.pbrt:2:1: error: \"float conedeltaangle\" must lie in [0, coneangle]\n"
            "LightSource \"spot\" \"float coneangle\" 10 \"float conedeltaangle\" 20\n^~~~~~~~~~~\n"
            "help: the falloff starts at coneangle - conedeltaangle\n");
}

TEST(PbrtImport, ObjectInstancesAreFlattened) {
  PbrtScene scene = import(world("ObjectBegin \"ball\"\n  Translate 1 0 0\n  Shape \"sphere\" \"float radius\" 0.5\nObjectEnd\n"
                                 "Translate 0 10 0\nObjectInstance \"ball\"\nTranslate 0 10 0\nObjectInstance \"ball\""),
                           in_memory());
  const Scene& s = scene.scene;
  ASSERT_EQ(s.shapes.size(), 2u);
  // The centre lives in the sphere's object frame (a mirroring here: the world is mirrored across x).
  EXPECT_EQ(raw(s.shapes[0].render_from_object(s.shapes[0].center)), glm::vec3(-1, 10, 0));
  EXPECT_EQ(raw(s.shapes[1].render_from_object(s.shapes[1].center)), glm::vec3(-1, 20, 0));
  EXPECT_EQ(import_error(world("ObjectInstance \"cup\"")),
            "scene.pbrt:2:16: error: no object named \"cup\"\nObjectInstance \"cup\"\n               ^~~~~\n"
            "help: ObjectBegin ... ObjectEnd defines one\n");
}

TEST(PbrtImport, IncludeAndPlyMeshesResolveAgainstTheMainFile) {
  // A minimal binary-free PLY: one triangle.
  std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  PbrtImportOptions options = in_memory({{"dir/geometry/parts.pbrt", "Include \"geometry/mesh.pbrt\"\n"},
                                         {"dir/geometry/mesh.pbrt", "Shape \"plymesh\" \"string filename\" \"tri.ply\"\n"},
                                         {"dir/tri.ply", ply}});
  PbrtScene scene = import(world("Include \"geometry/parts.pbrt\""), options);
  ASSERT_EQ(scene.scene.shapes.size(), 1u);
  EXPECT_EQ(scene.scene.shapes[0].indices.size(), 3u);
  // Errors inside an included file name the chain that led there.
  options = in_memory({{"dir/inc.pbrt", "Shape \"bilinearmesh\"\n"}});
  EXPECT_EQ(import_error(world("Include \"inc.pbrt\""), options),
            "In file included from scene.pbrt:2:1:\ndir/inc.pbrt:1:7: error: shape \"bilinearmesh\" is not supported\n"
            "Shape \"bilinearmesh\"\n      ^~~~~~~~~~~~~~\nhelp: supported: \"trianglemesh\", \"plymesh\", \"sphere\", \"disk\", "
            "\"cylinder\", \"cone\", \"paraboloid\", \"hyperboloid\", \"nurbs\", \"heightfield\", \"loopsubdiv\", \"curve\"\n");
  EXPECT_EQ(import_error(world("Shape \"plymesh\" \"string filename\" \"missing.ply\"")),
            "scene.pbrt:2:35: error: cannot read mesh 'dir/missing.ply': no such file\n"
            "Shape \"plymesh\" \"string filename\" \"missing.ply\"\n                                  ^~~~~~~~~~~~~\n");
  options = in_memory({{"dir/self.pbrt", "Include \"self.pbrt\"\n"}});
  EXPECT_NE(import_error(world("Include \"self.pbrt\""), options).find("error: Include nested more than 32 files deep"),
            std::string::npos);
}

// ---------------------------------------------------------------------------
// Robustness: any bytes give a scene or a PbrtImportError, never a crash.

// ---------------------------------------------------------------------------
// Plastic, glass, uber, image textures and the infinite light (pbrt-v3's
// materials/*.cpp, textures/imagemap.cpp, lights/infinite.cpp)

TEST(PbrtImport, PlasticGlassAndUberAsPbrtV3DefinesThem) {
  PbrtScene scene = import(world(
      "Material \"plastic\"\nShape \"sphere\"\n"                                                 // 0: pbrt's defaults
      "Material \"plastic\" \"rgb Kd\" [0.5 0.4 0.3] \"rgb Ks\" [0.2 0.2 0.2] \"float roughness\" 0.3 "
      "\"bool remaproughness\" \"false\"\nShape \"sphere\"\n"                                    // 1
      "Material \"plastic\" \"float roughness\" 0 \"bool remaproughness\" \"false\"\nShape \"sphere\"\n"  // 2
      "Material \"plastic\" \"rgb Ks\" [0 0 0]\nShape \"sphere\"\n"                              // 3: Lambert alone
      "Material \"glass\"\nShape \"sphere\"\n"                                                   // 4
      "Material \"glass\" \"rgb Kr\" [0.5 0.5 0.5] \"rgb Kt\" [0.9 0.8 0.7] \"float index\" 1.33\nShape \"sphere\"\n"
      "Material \"uber\"\nShape \"sphere\"\n"                                                    // 6: plastic
      "Material \"uber\" \"rgb Ks\" [0 0 0] \"rgb Kd\" [0.7 0.7 0.7]\nShape \"sphere\"\n"        // 7: matte
      "Material \"uber\" \"rgb Kd\" [0 0 0] \"rgb Ks\" [0 0 0] \"rgb Kr\" [1 1 1] \"rgb Kt\" [1 1 1] "
      "\"float eta\" 1.7\nShape \"sphere\"\n"                                                    // 8: glass
      "Material \"glass\" \"float eta\" 2 \"float index\" 1.2\nShape \"sphere\""));             // 9: eta wins
  const Scene& s = scene.scene;
  ASSERT_EQ(s.shapes.size(), 10u);
  auto material = [&](size_t shape) { return s.materials.at(s.shapes[shape].material); };
  EXPECT_TRUE(is<PlasticMaterial>(material(0)));
  EXPECT_EQ(sg::raw(diffuse(material(0)).value), glm::vec3(0.25f));
  EXPECT_EQ(sg::raw(as<PlasticMaterial>(material(0)).specular), glm::vec3(0.25f));
  EXPECT_NEAR(as<PlasticMaterial>(material(0)).alpha, pbrt_alpha(0.1), 1e-6);
  EXPECT_EQ(as<PlasticMaterial>(material(0)).ior, 1.5f);
  EXPECT_TRUE(as<PlasticMaterial>(material(0)).pbrt_v3_fresnel);  // FresnelDielectric(1.5, 1), as pbrt-v3 has it
  EXPECT_EQ(sg::raw(diffuse(material(1)).value), glm::vec3(0.5f, 0.4f, 0.3f));
  EXPECT_EQ(as<PlasticMaterial>(material(1)).alpha, 0.3f);
  EXPECT_EQ(as<PlasticMaterial>(material(2)).alpha, 0.001f);  // TrowbridgeReitzDistribution's floor
  EXPECT_TRUE(is<LambertMaterial>(material(3)));
  EXPECT_EQ(sg::raw(diffuse(material(3)).value), glm::vec3(0.25f));
  EXPECT_TRUE(is<GlassMaterial>(material(4)));
  EXPECT_EQ(sg::raw(as<GlassMaterial>(material(4)).reflectance), glm::vec3(1));
  EXPECT_EQ(sg::raw(as<GlassMaterial>(material(4)).transmittance), glm::vec3(1));
  EXPECT_EQ(as<GlassMaterial>(material(4)).ior, 1.5f);
  EXPECT_EQ(sg::raw(as<GlassMaterial>(material(5)).reflectance), glm::vec3(0.5f));
  EXPECT_EQ(sg::raw(as<GlassMaterial>(material(5)).transmittance), glm::vec3(0.9f, 0.8f, 0.7f));
  EXPECT_EQ(as<GlassMaterial>(material(5)).ior, 1.33f);
  EXPECT_TRUE(is<PlasticMaterial>(material(6)));
  EXPECT_FALSE(as<PlasticMaterial>(material(6)).pbrt_v3_fresnel);  // uber: FresnelDielectric(1, eta)
  EXPECT_NEAR(as<PlasticMaterial>(material(6)).alpha, pbrt_alpha(0.1), 1e-6);
  EXPECT_TRUE(is<LambertMaterial>(material(7)));
  EXPECT_EQ(sg::raw(diffuse(material(7)).value), glm::vec3(0.7f));
  EXPECT_TRUE(is<GlassMaterial>(material(8)));
  EXPECT_EQ(as<GlassMaterial>(material(8)).ior, 1.7f);
  EXPECT_EQ(as<GlassMaterial>(material(9)).ior, 2.0f);
  EXPECT_NE(scene.warnings.find("parameter \"float index\" of Material \"glass\" is not used"), std::string::npos);

  // "vroughness" defaults to 0 (pbrt-v3's): a lone "uroughness" is anisotropic.
  EXPECT_EQ(first_line(import_error(world(used("Material \"glass\" \"float uroughness\" 0.1")))),
            "scene.pbrt:2:10: error: an anisotropic Material \"glass\" (\"uroughness\" 0.1, \"vroughness\" 0) is not "
            "supported");
  // pbrt-v3 renders a plastic whose Kd + Ks exceed 1 (veach-mis: Kd 0.13 + Ks 1): so do we, with a warning.
  PbrtScene bright = import(world(used("Material \"plastic\" \"rgb Kd\" [0.8 0.8 0.8] \"rgb Ks\" [0.5 0.5 0.5]")));
  ASSERT_EQ(bright.scene.shapes.size(), 1u);
  const Material& kept = bright.scene.materials.at(bright.scene.shapes[0].material);
  EXPECT_EQ(sg::raw(diffuse(kept).value), glm::vec3(0.8f));
  EXPECT_EQ(sg::raw(as<PlasticMaterial>(kept).specular), glm::vec3(0.5f));
  EXPECT_EQ(bright.warnings,
            "scene.pbrt:2:10: warning: \"Kd\" + \"Ks\" of Material \"plastic\" exceed 1 in a channel (1.3): the "
            "surface can reflect more light than it receives\n"
            "Material \"plastic\" \"rgb Kd\" [0.8 0.8 0.8] \"rgb Ks\" [0.5 0.5 0.5]\n         ^~~~~~~~~\n"
            "help: rendered as pbrt-v3 renders it; lower Kd or Ks for a surface that conserves energy\n");
  EXPECT_EQ(import_error(world(used("Material \"uber\" \"rgb Kr\" [0.5 0.5 0.5]"))),
            "scene.pbrt:2:10: error: Material \"uber\" with both a diffuse or glossy part (Kd, Ks) and a specular one "
            "(Kr, Kt) is not supported\nMaterial \"uber\" \"rgb Kr\" [0.5 0.5 0.5]\n         ^~~~~~\n"
            "help: no material here sums them; uber renders as matte, plastic or glass when one of the two parts is "
            "black\n");
  // Opacity below 1: pbrt-v3's lobes times opacity, and the rest straight through (a glass of index 1), as a mix.
  PbrtScene leaf = import(world(used("Material \"uber\" \"rgb Kd\" [0.5 0.5 0.5] \"rgb Ks\" [0 0 0] "
                                     "\"rgb opacity\" [0.25 0.5 0.75]")));
  ASSERT_EQ(leaf.scene.shapes.size(), 1u);
  const Material& leaf_material = leaf.scene.materials.at(leaf.scene.shapes[0].material);
  ASSERT_TRUE(leaf_material.mix.has_value());
  EXPECT_EQ(sg::raw(leaf_material.mix->amount.value), glm::vec3(0.25f, 0.5f, 0.75f));
  EXPECT_EQ(sg::raw(diffuse(leaf.scene.materials.at(leaf_material.mix->first)).value), glm::vec3(0.5f));
  const GlassMaterial pass_through = as<GlassMaterial>(leaf.scene.materials.at(leaf_material.mix->second));
  EXPECT_EQ(sg::raw(pass_through.reflectance), glm::vec3(0));
  EXPECT_EQ(sg::raw(pass_through.transmittance), glm::vec3(1));
  EXPECT_EQ(pass_through.ior, 1.0f);
  EXPECT_EQ(leaf.warnings, "");
  EXPECT_FALSE(import(world(used("Material \"uber\" \"rgb opacity\" [1 1 1]"))).scene.materials.back().mix);
  EXPECT_EQ(first_line(import_error(world(used("Material \"uber\" \"rgb opacity\" [1.5 1 1]")))),
            "scene.pbrt:2:17: error: \"opacity\" of Material \"uber\" must lie in [0, 1] in every channel");
  EXPECT_EQ(import_error(world(used("Material \"uber\" \"float uroughness\" 0.1 \"float vroughness\" 0.2"))),
            "scene.pbrt:2:10: error: an anisotropic Material \"uber\" (\"uroughness\" 0.1, \"vroughness\" 0.2) is not "
            "supported\nMaterial \"uber\" \"float uroughness\" 0.1 \"float vroughness\" 0.2\n         ^~~~~~\n"
            "help: the microfacet lobe here is isotropic: give one \"roughness\"\n");
  EXPECT_EQ(import_error(world(used("Material \"glass\" \"float eta\" 0"))),
            "scene.pbrt:2:10: error: the index of refraction (\"eta\") of Material \"glass\" must lie in [1/16, 16], "
            "found 0\nMaterial \"glass\" \"float eta\" 0\n         ^~~~~~~\n");
}

// Glass has an outside, as emitters have a side: pbrt-v3's is its geometric
// normal's side, ours the winding's, so glass meshes are re-wound like
// emitters; so are translucent ones with glossy lobes (their interface's).
TEST(PbrtImport, GlassKeepsPbrtsOutside) {
  const std::string triangle = "Shape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0]\n";
  PbrtScene scene = import(world("Material \"glass\"\n" + triangle + "Material \"matte\"\n" + triangle +
                                 "Material \"translucent\"\n" + triangle + "Material \"translucent\" \"rgb Ks\" [0 0 0]\n" +
                                 triangle + "Material \"translucent\"\nReverseOrientation\n" + triangle),
                           in_memory());
  EXPECT_EQ(scene.scene.shapes.at(0).indices, (std::vector<uint32_t>{0, 2, 1}));  // mirrored world: re-wound
  EXPECT_EQ(scene.scene.shapes.at(1).indices, (std::vector<uint32_t>{0, 1, 2}));  // two-sided: left as written
  EXPECT_EQ(scene.scene.shapes.at(2).indices, (std::vector<uint32_t>{0, 2, 1}));  // translucent, as glass
  EXPECT_EQ(scene.scene.shapes.at(3).indices, (std::vector<uint32_t>{0, 1, 2}));  // diffuse lobes only: two-sided
  EXPECT_EQ(scene.scene.shapes.at(4).indices, (std::vector<uint32_t>{0, 1, 2}));  // mirrored and reversed
  EXPECT_EQ(import_error(world("Material \"glass\"\nReverseOrientation\nShape \"sphere\"")),
            "scene.pbrt:4:7: error: a glass, translucent or disney sphere turned inside out (ReverseOrientation) is not "
            "supported\n"
            "Shape \"sphere\"\n      ^~~~~~~~\nhelp: its outside would be the inside of the sphere\n");
}

// pbrt-v3's plastic swaps its Fresnel indices only on its normal's side (on the
// other its Fresnel sees a negative cosine and swaps them back): plastic meshes
// are re-wound to that side too (to "N"'s where given); plastic spheres turned
// inside out are not refused (they keep the swap outside, where pbrt-v3 has none).
TEST(PbrtImport, PlasticKeepsPbrtsOutside) {
  const std::string triangle = "Shape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0]\n";
  const std::string inward = "Shape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0] \"normal N\" [0 0 -1 0 0 -1 0 0 -1]\n";
  PbrtScene scene = import(world("Material \"plastic\"\n" + triangle + inward + "Material \"uber\"\n" + triangle +
                                 "Material \"plastic\"\nReverseOrientation\nShape \"sphere\""),
                           in_memory());
  EXPECT_EQ(scene.scene.shapes.at(0).indices, (std::vector<uint32_t>{0, 2, 1}));  // mirrored world: re-wound
  EXPECT_EQ(scene.scene.shapes.at(1).indices, (std::vector<uint32_t>{0, 1, 2}));  // to N's side
  EXPECT_EQ(scene.scene.shapes.at(2).indices, (std::vector<uint32_t>{0, 1, 2}));  // uber's Fresnel is not swapped
  EXPECT_EQ(scene.scene.shapes.size(), 4u);
}

// Images in memory, by file name: "grad.exr" is 1×2 linear (top row 0.2, bottom
// row 0.8), "paint.png" 1×1 sRGB-encoded 0.5, "hot.exr" 1×1 of 4.
PbrtImportOptions with_images() {
  PbrtImportOptions options = in_memory();
  options.read_image = [](const std::filesystem::path& path) {
    Image image;
    std::string name = path.filename().string();
    if (name == "grad.exr") {
      image.width = 1, image.height = 2, image.rgb = {0.2f, 0.2f, 0.2f, 0.8f, 0.8f, 0.8f};
    } else if (name == "paint.png" || name == "paint.tga") {
      image.width = 1, image.height = 1, image.rgb = {0.5f, 0.5f, 0.5f};
    } else if (name == "sky.hdr") {
      image.width = 2, image.height = 1, image.rgb = {3, 3, 3, 5, 5, 5};
    } else if (name == "hot.exr") {
      image.width = 1, image.height = 1, image.rgb = {4, 4, 4};
    } else {
      throw std::runtime_error("no such file");
    }
    return image;
  };
  return options;
}

TEST(PbrtImport, ImageTexturesAsPbrtV3ReadsThem) {
  PbrtScene scene = import(
      world("Texture \"g\" \"spectrum\" \"imagemap\" \"string filename\" \"grad.exr\" \"float uscale\" 2 "
            "\"float vdelta\" 0.5 \"string wrap\" \"clamp\" \"float scale\" 0.5 \"float maxanisotropy\" 4\n"
            "Texture \"p\" \"color\" \"imagemap\" \"string filename\" \"paint.png\" \"bool trilinear\" \"true\"\n"
            "Texture \"lin\" \"color\" \"imagemap\" \"string filename\" \"paint.tga\" \"bool gamma\" \"false\"\n"
            "Texture \"tinted\" \"color\" \"scale\" \"texture tex1\" \"p\" \"rgb tex2\" [0.5 1 1]\n"
            "Material \"matte\" \"texture Kd\" \"g\"\n"
            "Shape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0] \"point2 uv\" [0 0 1 0 0 1]\n"
            "Material \"plastic\" \"texture Kd\" \"tinted\" \"rgb Ks\" [0.1 0.1 0.1]\n"
            "Shape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0] \"float st\" [0 0 2 0 0 2]\n"
            "Material \"matte\" \"texture Kd\" \"lin\"\nShape \"sphere\""),
      with_images());
  const Scene& s = scene.scene;
  ASSERT_EQ(s.textures.size(), 3u);
  const ImageTexture& g = s.textures[0];
  EXPECT_EQ(g.colour_space, ColourSpace::linear);  // .exr: pbrt-v3's gamma is false
  EXPECT_EQ(g.mapping.u_scale, 2.0f);
  EXPECT_EQ(g.mapping.v_offset, 0.5f);
  EXPECT_EQ(g.mipmap->wrap(), TextureWrap::clamp);
  // Flipped as pbrt-v3 flips it (t = 0 is the bottom row), times "scale".
  EXPECT_EQ(sg::raw(g.mipmap->texel(0, 0, 0)), glm::vec3(0.4f));
  EXPECT_EQ(sg::raw(g.mipmap->texel(0, 0, 1)), glm::vec3(0.1f));
  EXPECT_EQ(s.textures[1].colour_space, ColourSpace::srgb);  // .png: sRGB-decoded
  EXPECT_NEAR(sg::raw(s.textures[1].mipmap->texel(0, 0, 0)).x, srgb_to_linear(0.5f), 1e-7);
  EXPECT_EQ(s.textures[2].colour_space, ColourSpace::linear);  // "gamma" false overrides the .tga default
  ASSERT_EQ(s.shapes.size(), 3u);
  const Material& textured = s.materials.at(s.shapes[0].material);
  EXPECT_EQ(diffuse(textured).texture, 0);
  EXPECT_EQ(sg::raw(diffuse(textured).value), glm::vec3(1));
  ASSERT_EQ(s.shapes[0].uvs.size(), 3u);
  EXPECT_EQ(s.shapes[0].uvs[2].v, 1.0f);
  const Material& tinted = s.materials.at(s.shapes[1].material);
  EXPECT_TRUE(is<PlasticMaterial>(tinted));
  EXPECT_EQ(diffuse(tinted).texture, 1);
  EXPECT_EQ(sg::raw(diffuse(tinted).value), glm::vec3(0.5f, 1, 1));  // "scale": the constant times the image
  EXPECT_EQ(s.shapes[1].uvs[1].u, 2.0f);                      // "st" when there is no "uv"
  EXPECT_EQ(diffuse(s.materials.at(s.shapes[2].material)).texture, 2);
  EXPECT_EQ(g.filter, TextureFilter::ewa);  // pbrt-v3's default
  EXPECT_EQ(g.max_anisotropy, 4.0f);
  EXPECT_EQ(s.textures[1].filter, TextureFilter::trilinear);
  EXPECT_EQ(s.textures[2].max_anisotropy, 8.0f);
  EXPECT_EQ(scene.warnings, "");
  EXPECT_EQ(import_error(world(used("Texture \"h\" \"color\" \"imagemap\" \"string filename\" \"paint.png\" "
                                    "\"float maxanisotropy\" 0\nMaterial \"matte\" \"texture Kd\" \"h\"")),
                         with_images()),
            "scene.pbrt:2:62: error: \"float maxanisotropy\" of Texture \"h\" must lie in (0, 1e6]\n"
            "Texture \"h\" \"color\" \"imagemap\" \"string filename\" \"paint.png\" \"float maxanisotropy\" 0\n"
            "                                                             ^~~~~~~~~~~~~~~~~~~~~\n");

  const std::string hot = "Texture \"h\" \"color\" \"imagemap\" \"string filename\" \"hot.exr\" \"bool trilinear\" \"true\"\n";
  // An image above 1 as a reflectance renders as pbrt-v3 renders it, warned (its own test below for patterns).
  EXPECT_EQ(import(world(used(hot + "Material \"matte\" \"texture Kd\" \"h\"")), with_images()).warnings,
            "scene.pbrt:3:31: warning: this texture reaches 4: as \"Kd\" of Material \"matte\" the surface reflects more "
            "light than it receives where it exceeds 1\n"
            "Material \"matte\" \"texture Kd\" \"h\"\n                              ^~~\n"
            "help: rendered as pbrt-v3 renders it; lower the texture (a \"scale\" texture) for a surface that conserves "
            "energy\n");
  EXPECT_EQ(import_error(world(used(hot + "Material \"plastic\" \"texture Ks\" \"h\"")), with_images()),
            "scene.pbrt:3:20: error: an image texture as \"Ks\" of Material \"plastic\" is not supported\n"
            "Material \"plastic\" \"texture Ks\" \"h\"\n                   ^~~~~~~~~~~~\n"
            "help: only diffuse reflectances (\"Kd\" of matte, plastic, substrate, translucent and uber) take textures here\n");
  // A format pbrt-v3 does not read is read all the same (the reader decides), with a warning.
  EXPECT_EQ(import_error(world(used_texture("Texture \"t\" \"color\" \"imagemap\" \"string filename\" \"photo.jpg\"")), with_images()),
            "scene.pbrt:2:50: error: cannot read image 'dir/photo.jpg': no such file\n"
            "Texture \"t\" \"color\" \"imagemap\" \"string filename\" \"photo.jpg\"\n"
            "                                                 ^~~~~~~~~~~\n");
  EXPECT_EQ(import_error(world(used_texture("Texture \"t\" \"color\" \"imagemap\" \"string filename\" \"gone.png\"")), with_images()),
            "scene.pbrt:2:50: error: cannot read image 'dir/gone.png': no such file\n"
            "Texture \"t\" \"color\" \"imagemap\" \"string filename\" \"gone.png\"\n"
            "                                                 ^~~~~~~~~~\n");
  EXPECT_EQ(import_error(world(used_float_texture("Texture \"t\" \"float\" \"imagemap\" \"string filename\" \"grad.exr\"")), with_images()),
            "scene.pbrt:3:20: error: an image texture as \"roughness\" of Material \"plastic\" is not supported\n"
            "Material \"plastic\" \"texture roughness\" \"t\"\n                   ^~~~~~~~~~~~~~~~~~~\n"
            "help: only \"bumpmap\" reads a float texture here; the others take numbers\n");
  EXPECT_EQ(import_error(world(used_texture("Texture \"t\" \"color\" \"imagemap\" \"string filename\" \"grad.exr\" "
                                            "\"string mapping\" \"sphere\"")),
                         with_images()),
            "scene.pbrt:2:61: error: texture mapping \"sphere\" is unknown\n"
            "Texture \"t\" \"color\" \"imagemap\" \"string filename\" \"grad.exr\" \"string mapping\" \"sphere\"\n"
            "                                                            ^~~~~~~~~~~~~~~~\n"
            "help: pbrt-v3 has \"uv\", \"spherical\", \"cylindrical\" and \"planar\" (and would use \"uv\")\n");
  EXPECT_EQ(import_error(world("Shape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0] \"float uv\" [0 0 1 0]")),
            "scene.pbrt:2:63: error: \"float uv\" needs one (u, v) pair per vertex of \"point P\": 4 values for 3 "
            "vertices\nShape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0] \"float uv\" [0 0 1 0]\n"
            "                                                              ^~~~~~~~~\n");
}

// pbrt's sphere (u, v) are about its object-space z axis: the object frame's
// rotation survives the import (in render_from_object), the centre is the same point.
TEST(PbrtImport, SpheresKeepTheirObjectFrame) {
  PbrtScene scene = import(world("Translate 1 2 3\nRotate 90 1 0 0\nShape \"sphere\" \"float radius\" 2"), in_memory({}, 0.5));
  const Shape& sphere = scene.scene.shapes.at(0);
  EXPECT_EQ(sg::raw(sphere.radius), 1.0f);
  glm::vec3 centre = raw(sphere.render_from_object(sphere.center));
  EXPECT_NEAR(centre.x, -0.5f, 1e-6);  // mirrored across x, in half metres
  EXPECT_NEAR(centre.y, 1.0f, 1e-6);
  EXPECT_NEAR(centre.z, 1.5f, 1e-6);
  // Object +z (the sphere's pole, v = 1) is pbrt's world -y after Rotate 90 about x.
  glm::vec3 pole = sg::raw(sphere.render_from_object(direction<Object>(0, 0, 1)));
  EXPECT_NEAR(pole.y, -1, 1e-6);
}

// pbrt-v3's bump maps (bump-sphere.pbrt's): a float image texture, scaled by a
// constant, displaces the surface by that many scene units; a constant one
// changes no normal.
TEST(PbrtImport, BumpMapsAsPbrtV3ReadsThem) {
  PbrtScene scene = import(
      world("Texture \"g\" \"float\" \"imagemap\" \"string filename\" \"grad.exr\"\n"
            "Texture \"s\" \"float\" \"scale\" \"texture tex1\" \"g\" \"float tex2\" [-0.1]\n"
            "Texture \"c\" \"float\" \"constant\" \"float value\" 0.5\n"
            "Material \"uber\" \"rgb Kd\" [.8 .7 .4] \"rgb Ks\" [.05 .05 .05] \"float roughness\" .01 "
            "\"texture bumpmap\" \"s\"\nShape \"sphere\"\n"
            "Material \"matte\" \"texture bumpmap\" \"c\"\nShape \"sphere\""),
      with_images());
  const Scene& s = scene.scene;
  ASSERT_EQ(s.materials.size(), 2u);
  ASSERT_TRUE(s.materials[0].bump.has_value());
  EXPECT_EQ(s.materials[0].bump->texture, 0);
  EXPECT_FLOAT_EQ(sg::raw(s.materials[0].bump->scale), static_cast<float>(-0.1 * in_memory().metres_per_unit));
  EXPECT_EQ(s.textures[0].colour_space, ColourSpace::linear);
  EXPECT_FALSE(s.materials[1].bump.has_value());

  EXPECT_EQ(import_error(world(used("Texture \"r\" \"color\" \"constant\"\nMaterial \"matte\" \"texture bumpmap\" \"r\""))),
            "scene.pbrt:3:36: error: no float texture named \"r\"\n"
            "Material \"matte\" \"texture bumpmap\" \"r\"\n                                   ^~~\n"
            "help: Texture \"r\" \"float\" ... defines one\n");
  EXPECT_EQ(first_line(import_error(
                world(used("Texture \"a\" \"float\" \"imagemap\" \"string filename\" \"grad.exr\"\n"
                           "Texture \"b\" \"float\" \"scale\" \"texture tex1\" \"a\" \"texture tex2\" \"a\"\n"
                           "Material \"matte\" \"texture bumpmap\" \"b\"")),
                with_images())),
            "scene.pbrt:3:29: error: an image texture in a \"scale\" with another texture is not supported");
}

// pbrt-v3's MixTexture and ScaleTexture: constants fold, a constant times one
// texture stays that (a mix whose other part weighs 0 too), two patterns (the
// hackmad/pbrt-v3-rs scenes' windy × checkerboard) become a pattern of both;
// uv and bilerp are patterns of their own.
TEST(PbrtImport, MixAndScaleTextures) {
  PbrtScene scene = import(world(
      "Texture \"w\" \"color\" \"windy\"\n"                                                         // pattern 0
      "Texture \"c\" \"color\" \"checkerboard\" \"float uscale\" -16\n"                            // pattern 1
      "Texture \"k\" \"color\" \"mix\" \"rgb tex1\" [0.2 0.4 0.6] \"rgb tex2\" [1 1 1] \"float amount\" 0.25\n"
      "Material \"matte\" \"texture Kd\" \"k\"\nShape \"sphere\"\n"                               // 0: constant
      "Texture \"a\" \"color\" \"mix\" \"texture tex1\" \"w\" \"rgb tex2\" [0 0 0] \"float amount\" 0.4\n"
      "Material \"matte\" \"texture Kd\" \"a\"\nShape \"sphere\"\n"                               // 1: 0.6 × windy
      "Texture \"m\" \"color\" \"mix\" \"texture tex1\" \"w\" \"texture tex2\" \"c\" \"float amount\" 0.68\n"
      "Material \"matte\" \"texture Kd\" \"m\"\nShape \"sphere\"\n"                               // 2: pattern 2
      "Texture \"p\" \"color\" \"scale\" \"texture tex1\" \"w\" \"texture tex2\" \"c\"\n"
      "Material \"matte\" \"texture Kd\" \"p\"\nShape \"sphere\"\n"                               // 3: pattern 3
      "Texture \"uv\" \"color\" \"uv\" \"float uscale\" -1\n"
      "Material \"matte\" \"texture Kd\" \"uv\"\nShape \"sphere\"\n"                              // 4: pattern 4
      "Texture \"b\" \"color\" \"bilerp\" \"rgb v00\" [1 1 1] \"rgb v01\" [1 0 0]\n"
      "Material \"matte\" \"texture Kd\" \"b\"\nShape \"sphere\""));                                // 5: pattern 5
  const Scene& s = scene.scene;
  ASSERT_EQ(s.shapes.size(), 6u);
  auto kd = [&](size_t shape) { return diffuse(s.materials.at(s.shapes[shape].material)); };
  EXPECT_FALSE(kd(0).textured());
  const glm::vec3 folded = sg::raw(kd(0).value);  // (1 − 0.25) tex1 + 0.25 tex2, folded in double
  EXPECT_NEAR(folded.x, 0.4f, 1e-6);
  EXPECT_NEAR(folded.y, 0.55f, 1e-6);
  EXPECT_NEAR(folded.z, 0.7f, 1e-6);
  EXPECT_EQ(kd(1).pattern, 0);
  EXPECT_NEAR(sg::raw(kd(1).value).x, 0.6f, 1e-6);
  ASSERT_EQ(s.patterns.size(), 6u);
  EXPECT_EQ(kd(2).pattern, 2);
  const MixPattern& mix = std::get<MixPattern>(s.patterns[2].pattern);
  EXPECT_TRUE(std::holds_alternative<WindyPattern>(mix.first.pattern->pattern));
  EXPECT_TRUE(std::holds_alternative<CheckerboardPattern>(mix.second.pattern->pattern));
  EXPECT_FALSE(mix.amount.pattern);
  EXPECT_NEAR(sg::raw(mix.amount.value).x, 0.68f, 1e-6);
  EXPECT_EQ(kd(3).pattern, 3);
  EXPECT_TRUE(std::holds_alternative<ProductPattern>(s.patterns[3].pattern));
  EXPECT_EQ(std::get<UvPattern>(s.patterns[4].pattern).mapping.u_scale, -1);
  const BilerpPattern& bilerp = std::get<BilerpPattern>(s.patterns[5].pattern);
  EXPECT_EQ(sg::raw(bilerp.v01), glm::vec3(1, 0, 0));
  EXPECT_EQ(sg::raw(bilerp.v10), glm::vec3(0));  // pbrt-v3's defaults: v10 0, v11 1
  EXPECT_EQ(sg::raw(bilerp.v11), glm::vec3(1));
  EXPECT_EQ(scene.warnings, "");
  EXPECT_EQ(first_line(import_error(world(used("Texture \"u\" \"float\" \"uv\"\nMaterial \"matte\" \"texture bumpmap\" \"u\"")))),
            "scene.pbrt:2:21: error: texture \"uv\" is not supported");
}

// pbrt-v3 clamps a texture's reflectance below 0 only, and so do we: a noise
// sum that goes above 1 (wrinkled's turbulence at 8 octaves: about 1.8) is
// rendered as it is and said once per texture, at its first use; a
// checkerboard of colours in [0, 1] never is. As a mix's amount (a weight) it
// is clamped to 1.
TEST(PbrtImport, PatternsAboveOneAreRenderedWithAWarning) {
  PbrtScene scene = import(world(
      "Texture \"t\" \"color\" \"wrinkled\" \"integer octaves\" 8 \"float roughness\" 0.75\n"
      "Texture \"c\" \"color\" \"checkerboard\"\n"
      "Material \"matte\" \"texture Kd\" \"t\"\nShape \"sphere\"\n"
      "Material \"plastic\" \"texture Kd\" \"t\" \"rgb Ks\" [0 0 0]\nShape \"sphere\"\n"
      "Material \"matte\" \"texture Kd\" \"c\"\nShape \"sphere\""));
  const std::string& w = scene.warnings;
  EXPECT_EQ(w.rfind("scene.pbrt:4:31: warning: this texture reaches 1.", 0), 0u) << w;
  EXPECT_NE(w.find(": as \"Kd\" of Material \"matte\" the surface reflects more light than it receives where it exceeds 1\n"),
            std::string::npos)
      << w;
  EXPECT_NE(w.find("help: rendered as pbrt-v3 renders it; lower the texture (a \"scale\" texture) for a surface that "
                   "conserves energy\n"),
            std::string::npos);
  EXPECT_EQ(w.find("warning:", 30), std::string::npos) << "once per texture: " << w;
  EXPECT_GT(sg::max_component(largest_value(scene.scene.patterns.at(0).pattern)), 1.5f);
  EXPECT_EQ(sg::max_component(largest_value(scene.scene.patterns.at(1).pattern)), 1.0f);

  const std::string mixed = import(world("Texture \"t\" \"color\" \"wrinkled\" \"integer octaves\" 8 \"float roughness\" 0.75\n"
                                         "MakeNamedMaterial \"a\" \"string type\" \"matte\"\n"
                                         "MakeNamedMaterial \"b\" \"string type\" \"mirror\"\n"
                                         "Material \"mix\" \"texture amount\" \"t\" \"string namedmaterial1\" \"a\" "
                                         "\"string namedmaterial2\" \"b\"\nShape \"sphere\""))
                                .warnings;
  EXPECT_NE(mixed.find(": as \"amount\" of Material \"mix\" it is clamped to 1 where it exceeds 1\n"), std::string::npos)
      << mixed;
}

// Float procedural textures (pbrt-v3's FBmTexture<Float>, a float checkerboard, ...) are bump maps too:
// their numbers are displacements, any finite value, a "scale" of one by a constant included.
TEST(PbrtImport, ProceduralBumpMaps) {
  PbrtScene scene = import(world(
      "Texture \"n\" \"float\" \"wrinkled\" \"float roughness\" 0.6 \"integer octaves\" 4\n"
      "Texture \"s\" \"float\" \"scale\" \"texture tex1\" \"n\" \"float tex2\" 0.02\n"
      "Texture \"c\" \"float\" \"checkerboard\" \"float tex1\" -2 \"float tex2\" 3 \"float uscale\" 8\n"
      "Material \"matte\" \"texture bumpmap\" \"s\"\nShape \"sphere\"\n"
      "Material \"plastic\" \"texture bumpmap\" \"c\"\nShape \"sphere\""));
  const Scene& s = scene.scene;
  ASSERT_EQ(s.materials.size(), 2u);
  ASSERT_EQ(s.patterns.size(), 2u);
  ASSERT_TRUE(s.materials[0].bump && s.materials[1].bump);
  EXPECT_EQ(s.materials[0].bump->texture, -1);
  EXPECT_EQ(s.materials[0].bump->pattern, 0);
  EXPECT_FLOAT_EQ(sg::raw(s.materials[0].bump->scale), static_cast<float>(0.02 * in_memory().metres_per_unit));
  const auto& noise = std::get<FbmPattern>(s.patterns[0].pattern);
  EXPECT_TRUE(noise.turbulence);
  EXPECT_EQ(noise.octaves, 4);
  const auto& board = std::get<CheckerboardPattern>(s.patterns[1].pattern);
  EXPECT_EQ(sg::raw(board.even)[0], -2.0f);  // a displacement: not clamped to [0, 1]
  EXPECT_EQ(sg::raw(board.odd)[0], 3.0f);
  PatternLookup at{.u = 0.01f, .v = 0.01f};
  EXPECT_EQ(evaluate_number(s.patterns[1].pattern, at), -2.0f);
  EXPECT_EQ(first_line(import_error(world(used("Texture \"c\" \"float\" \"checkerboard\" \"float tex1\" 1e7\n"
                                                "Material \"matte\" \"texture bumpmap\" \"c\"")))),
            "scene.pbrt:2:36: error: \"tex1\" of Texture \"c\" must lie in [-1e6, 1e6]");
}

TEST(PbrtImport, InfiniteLightAsPbrtV3DefinesIt) {
  PbrtScene scene = import(world("AttributeBegin\nRotate -90 1 0 0\nLightSource \"infinite\" \"rgb L\" [1 2 3] "
                                 "\"rgb scale\" [2 2 2] \"string mapname\" \"grad.exr\" \"integer samples\" 4\nAttributeEnd"),
                           with_images());
  ASSERT_TRUE(scene.scene.environment.has_value());
  const EnvironmentLight& light = *scene.scene.environment;
  EXPECT_EQ(sg::raw(light.radiance), glm::vec3(2, 4, 6));
  EXPECT_EQ(light.file, "grad.exr");
  ASSERT_TRUE(light.map);
  // Not flipped, not decoded: row 0 (θ = 0, the map's +z) is the file's top row.
  EXPECT_EQ(sg::raw(light.map->texel(0, 0, 0)), glm::vec3(0.2f));
  EXPECT_EQ(light.map->wrap(), TextureWrap::longitude_latitude);
  // Light +z goes to pbrt's world +y (Rotate -90 about x); light +x to pbrt's
  // +x, which the mirrored import world (default camera) has at -x.
  glm::vec3 pole = sg::raw(light.render_from_light(direction<LightSpace>(0, 0, 1)));
  glm::vec3 x = sg::raw(light.render_from_light(direction<LightSpace>(1, 0, 0)));
  EXPECT_NEAR(pole.y, 1, 1e-6);
  EXPECT_NEAR(x.x, -1, 1e-6);
  EXPECT_TRUE(scene.warnings.empty()) << scene.warnings;

  // A .hdr map (pbrt-v3 reads none, and would light the scene with L alone) is read, with a warning, once.
  PbrtScene hdr = import(world("LightSource \"infinite\" \"string mapname\" \"sky.hdr\""), with_images());
  ASSERT_TRUE(hdr.scene.environment->map);
  EXPECT_EQ(sg::raw(hdr.scene.environment->map->texel(0, 1, 0)), glm::vec3(5));
  EXPECT_EQ(hdr.warnings,
            "scene.pbrt:2:41: warning: pbrt-v3 reads no image format \".hdr\"; read here as the file says\n"
            "LightSource \"infinite\" \"string mapname\" \"sky.hdr\"\n"
            "                                        ^~~~~~~~~\n"
            "help: pbrt-v3 reads .exr, .png, .tga and .pfm files: it would render a grey texture, or an infinite "
            "light's constant radiance without its map\n");

  EXPECT_EQ(sg::raw(import(world("LightSource \"infinite\"")).scene.environment->radiance), glm::vec3(1));
  EXPECT_EQ(import_error(world("LightSource \"infinite\"\nLightSource \"infinite\" \"rgb L\" [1 1 1]")),
            "scene.pbrt:3:13: error: a second infinite light\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
            "            ^~~~~~~~~~\nhelp: the renderer has one environment light per scene (the first is at line 2)\n");
  EXPECT_EQ(import_error(world("Scale 1 2 1\nLightSource \"infinite\"")),
            "scene.pbrt:3:1: error: an infinite light under a transform that scales unevenly or shears is not "
            "supported\nLightSource \"infinite\"\n^~~~~~~~~~~\nhelp: it would distort the map; rotate it only\n");
}

const char* const kRichScene = R"pbrt(# a scene touching every supported directive
LookAt 0 1 -5  0 1 0  0 1 0
Camera "perspective" "float fov" [45] "float lensradius" 0.01 "float focaldistance" 5
Film "image" "integer xresolution" [16] "integer yresolution" [12] "string filename" "out.exr"
Sampler "halton" "integer pixelsamples" 4
Integrator "path" "integer maxdepth" [5]
PixelFilter "box"
WorldBegin
CoordinateSystem "here"
LightSource "point" "color I" [5 5 5] "point from" [0 4 0]
LightSource "spot" "rgb I" [9 9 9] "point from" [1 3 0] "point to" [0 0 0] "float coneangle" 30
Texture "t" "color" "constant" "rgb value" [0.2 0.4 0.6]
MakeNamedMaterial "white" "string type" ["matte"] "rgb Kd" [0.7 0.7 0.7]
MakeNamedMaterial "coat" "string type" "plastic" "rgb Kd" [0.3 0.3 0.3] "float roughness" 0.2
MakeNamedMaterial "gold" "string type" "metal" "spectrum eta" "metal-Au-eta" "spectrum k" [400 3.9 700 2] "float roughness" 0.05
LightSource "infinite" "rgb L" [0.1 0.1 0.1] "integer samples" 2
AttributeBegin
  AreaLightSource "area" "color L" [4 4 4] "bool twosided" "true" "integer nsamples" 4
  Translate 0 2.9 0
  Shape "trianglemesh" "point P" [-0.5 0 -0.5 0.5 0 -0.5 0.5 0 0.5 -0.5 0 0.5] "integer indices" [0 1 2 0 2 3]
AttributeEnd
TransformBegin
  Rotate 30 0 1 0
  Scale 1 1 1
  ConcatTransform [1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1]
  Material "matte" "texture Kd" "t"
  Shape "sphere" "float radius" 0.5
  NamedMaterial "gold"
  Shape "sphere" "float radius" 0.25
TransformEnd
ObjectBegin "box"
  NamedMaterial "coat"
  Shape "trianglemesh" "point P" [0 0 0 1 0 0 1 1 0] "float uv" [0 0 1 0 1 1]
ObjectEnd
ObjectInstance "box"
CoordSysTransform "here"
ReverseOrientation
Material "glass" "float eta" 1.4
Transform [1 0 0 0  0 1 0 0  0 0 1 0  0 -1 0 1]
Shape "trianglemesh" "point P" [-5 0 -5 5 0 -5 5 0 5 -5 0 5] "integer indices" [0 1 2 0 2 3] "normal N" [0 1 0 0 1 0 0 1 0 0 1 0]
WorldEnd
)pbrt";

void expect_scene_or_error(const std::string& text, const char* what) {
  try {
    (void)import(text);
  } catch (const PbrtImportError&) {
  } catch (const std::exception& other) {
    ADD_FAILURE() << what << ": a " << typeid(other).name() << " escaped: " << other.what();
  }
}

TEST(PbrtImport, TheRichSceneImports) {
  PbrtScene scene = import(kRichScene);
  EXPECT_EQ(scene.warnings.find("vertex normals"), std::string::npos) << scene.warnings;  // they shade now
  EXPECT_EQ(scene.scene.shapes.size(), 5u);
  // The floor's "N" (0 1 0), unit length and still along the floor's normal after the import's transforms.
  const auto with_normals = std::find_if(scene.scene.shapes.begin(), scene.scene.shapes.end(),
                                         [](const Shape& s) { return !s.normals.empty(); });
  ASSERT_NE(with_normals, scene.scene.shapes.end());
  const Shape& floor = *with_normals;
  ASSERT_EQ(floor.normals.size(), 4u);
  const glm::dvec3 a(sg::raw(floor.positions[0])), b(sg::raw(floor.positions[1])), c(sg::raw(floor.positions[2]));
  const glm::dvec3 across = glm::normalize(glm::cross(b - a, c - a));
  for (const normal<Object>& n : floor.normals) EXPECT_NEAR(std::abs(glm::dot(glm::dvec3(sg::raw(n)), across)), 1.0, 1e-6);
  EXPECT_EQ(scene.scene.point_lights.size(), 1u);
  EXPECT_EQ(scene.scene.spot_lights.size(), 1u);
  EXPECT_TRUE(scene.scene.environment.has_value());
}

TEST(PbrtImport, EveryTruncationAndRandomDamageGivesASceneOrAnError) {
  const std::string text = kRichScene;
  for (size_t length = 0; length < text.size(); ++length) expect_scene_or_error(text.substr(0, length), "a prefix");
  std::mt19937 random(7);
  const std::string alphabet = "[]\"# \n\t0123456789.-+eE\\abcxyzWorldBeginEndShapeAttribute";
  for (int trial = 0; trial < 3000; ++trial) {
    std::string damaged = text;
    int edits = 1 + static_cast<int>(random() % 4);
    for (int e = 0; e < edits; ++e) {
      size_t at = random() % damaged.size();
      switch (random() % 4) {
        case 0: damaged[at] = alphabet[random() % alphabet.size()]; break;
        case 1: damaged.erase(at, 1 + random() % 8); break;
        case 2: damaged.insert(at, 1, static_cast<char>(random() % 256)); break;
        default: damaged.insert(at, damaged.substr(random() % damaged.size(), random() % 40)); break;
      }
      if (damaged.empty()) damaged = "x";
    }
    expect_scene_or_error(damaged, "a damaged copy");
  }
}

}  // namespace
}  // namespace safegi::render
