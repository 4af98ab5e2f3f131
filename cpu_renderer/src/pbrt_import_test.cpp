// The pbrt-v3 reader: tokens, directive grammar, diagnostics (exact text),
// the mapping into Scene (camera, handedness, units, materials, lights,
// shapes, instances, Include), and that no input crashes it.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "pbrt_tokenizer.hpp"
#include "safegi/cpu_renderer/pbrt_import.hpp"

namespace safegi::render {
namespace {

// A file system in memory: Include and plymesh read from it, never from disk.
PbrtImportOptions in_memory(std::map<std::string, std::string> files = {}, double metres = 1) {
  PbrtImportOptions options;
  options.metres_per_unit = metres;
  options.read_file = [files](const std::filesystem::path& path, std::string& error) -> std::optional<std::string> {
    auto found = files.find(path.lexically_normal().string());
    if (found == files.end()) {
      error = "no such file";
      return std::nullopt;
    }
    return found->second;
  };
  return options;
}

PbrtScene import(const std::string& text, const PbrtImportOptions& options = in_memory()) {
  return parse_pbrt_scene(text, "scene.pbrt", "dir", options);
}

std::string import_error(const std::string& text, const PbrtImportOptions& options = in_memory()) {
  try {
    import(text, options);
  } catch (const PbrtImportError& error) {
    return error.what();
  }
  return "(no error)";
}

// The smallest complete scene around some world-block text.
std::string world(const std::string& body) { return "WorldBegin\n" + body + "\nWorldEnd\n"; }

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
  EXPECT_EQ(import_error(world("Shape \"disk\"")),
            "scene.pbrt:2:7: error: shape \"disk\" is not supported\nShape \"disk\"\n      ^~~~~~\n"
            "help: supported: \"trianglemesh\", \"plymesh\", \"sphere\"\n");
  EXPECT_EQ(import_error(world("Material \"metal\"")),
            "scene.pbrt:2:10: error: material \"metal\" is not supported\nMaterial \"metal\"\n"
            "         ^~~~~~~\nhelp: supported: \"matte\", \"mirror\", \"plastic\", \"glass\", \"uber\"\n");
  EXPECT_EQ(import_error(world("Material \"matte\" \"float sigma\" [20]")),
            "scene.pbrt:2:18: error: \"float sigma\" of Material \"matte\" is not supported: Oren-Nayar roughness "
            "(only sigma 0, Lambert)\nMaterial \"matte\" \"float sigma\" [20]\n                 ^~~~~~~~~~~~~\n");
  EXPECT_EQ(import_error(world("LightSource \"distant\"")),
            "scene.pbrt:2:13: error: light \"distant\" is not supported\nLightSource \"distant\"\n"
            "            ^~~~~~~~~\nhelp: supported: \"point\", \"spot\", \"infinite\"\n");
  EXPECT_EQ(import_error(world("Texture \"t\" \"spectrum\" \"checkerboard\"")),
            "scene.pbrt:2:24: error: texture \"checkerboard\" is not supported\n"
            "Texture \"t\" \"spectrum\" \"checkerboard\"\n"
            "                       ^~~~~~~~~~~~~~\nhelp: supported: \"constant\", \"imagemap\", \"scale\"\n");
  EXPECT_EQ(import_error("Integrator \"bdpt\"\n" + world("")),
            "scene.pbrt:1:12: error: integrator \"bdpt\" is not supported\nIntegrator \"bdpt\"\n           ^~~~~~\n"
            "help: supported: \"path\", \"directlighting\" (and \"whitted\", rendered as direct lighting)\n");
  EXPECT_EQ(import_error("ActiveTransform EndTime\n"),
            "scene.pbrt:1:17: error: animated transforms (ActiveTransform EndTime) are not supported\n"
            "ActiveTransform EndTime\n                ^~~~~~~\n");
  EXPECT_EQ(import_error(world("Shape \"sphere\" \"float zmax\" [0.5]")),
            "scene.pbrt:2:16: error: \"float zmax\" of Shape \"sphere\" is not supported: partial spheres\n"
            "Shape \"sphere\" \"float zmax\" [0.5]\n               ^~~~~~~~~~~~\n");
  EXPECT_EQ(import_error(world("Material \"matte\" \"rgb Kd\" [1.5 0 0]")),
            "scene.pbrt:2:18: error: \"Kd\" of Material \"matte\" must lie in [0, 1] in every channel\n"
            "Material \"matte\" \"rgb Kd\" [1.5 0 0]\n                 ^~~~~~~~\n"
            "help: above 1 a surface reflects more light than it receives\n");
  EXPECT_EQ(import_error(world("Scale 1 2 1\nShape \"sphere\"")),
            "scene.pbrt:3:7: error: a sphere under a transform that scales unevenly (an ellipsoid) is not supported\n"
            "Shape \"sphere\"\n      ^~~~~~~~\n");
}

TEST(PbrtImport, IgnoredParametersAreWarnings) {
  PbrtScene scene = import(world("Shape \"sphere\" \"float radius\" 1 \"float raduis\" 2"));
  EXPECT_EQ(scene.warnings,
            "scene.pbrt:2:33: warning: parameter \"float raduis\" of Shape \"sphere\" is not used\n"
            "Shape \"sphere\" \"float radius\" 1 \"float raduis\" 2\n                                ^~~~~~~~~~~~~~\n"
            "help: pbrt-v3 ignores it too (misspelt?)\n");
  EXPECT_EQ(import("PixelFilter \"gaussian\"\n" + world("")).warnings,
            "scene.pbrt:1:1: warning: pixels are reconstructed with a box filter one pixel wide, not this filter\n"
            "PixelFilter \"gaussian\"\n^~~~~~~~~~~~~~~~~~~~~~\n"
            "help: edges are slightly sharper than pbrt-v3's; the radiance is the same\n");
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
  EXPECT_EQ(material(0).type, Material::Type::lambert);
  EXPECT_EQ(sg::raw(material(0).diffuse), glm::vec3(0.5f));
  EXPECT_EQ(sg::raw(material(1).diffuse), glm::vec3(0.8f, 0.1f, 0.1f));
  EXPECT_EQ(sg::raw(material(2).diffuse), glm::vec3(0, 0.5f, 0));
  EXPECT_EQ(material(3).type, Material::Type::mirror);
  EXPECT_EQ(sg::raw(material(3).specular), glm::vec3(0.9f));  // pbrt-v3's default Kr
  EXPECT_EQ(sg::raw(material(4).diffuse), glm::vec3(0.3f));
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
  options = in_memory({{"dir/inc.pbrt", "Shape \"cone\"\n"}});
  EXPECT_EQ(import_error(world("Include \"inc.pbrt\""), options),
            "In file included from scene.pbrt:2:1:\ndir/inc.pbrt:1:7: error: shape \"cone\" is not supported\n"
            "Shape \"cone\"\n      ^~~~~~\nhelp: supported: \"trianglemesh\", \"plymesh\", \"sphere\"\n");
  EXPECT_EQ(import_error(world("Shape \"plymesh\" \"string filename\" \"missing.ply\"")),
            "scene.pbrt:2:35: error: cannot read mesh 'dir/missing.ply': no such file\n"
            "Shape \"plymesh\" \"string filename\" \"missing.ply\"\n                                  ^~~~~~~~~~~~~\n");
  options = in_memory({{"dir/self.pbrt", "Include \"self.pbrt\"\n"}});
  EXPECT_NE(import_error(world("Include \"self.pbrt\""), options).find("error: Include nested more than 32 files deep"),
            std::string::npos);
}

// ---------------------------------------------------------------------------
// Robustness: any bytes give a scene or a PbrtImportError, never a crash.

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
TransformEnd
ObjectBegin "box"
  NamedMaterial "white"
  Shape "trianglemesh" "point P" [0 0 0 1 0 0 1 1 0] "float uv" [0 0 1 0 1 1]
ObjectEnd
ObjectInstance "box"
CoordSysTransform "here"
ReverseOrientation
Material "mirror" "rgb Kr" [0.9 0.9 0.9]
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
  const std::string expected =
      "scene.pbrt:35:7: warning: vertex normals \"N\" only orient emitters here: surfaces are shaded with their "
      "geometric normals\n";
  EXPECT_EQ(scene.warnings.substr(0, expected.size()), expected);
  EXPECT_EQ(scene.scene.shapes.size(), 4u);
  EXPECT_EQ(scene.scene.point_lights.size(), 1u);
  EXPECT_EQ(scene.scene.spot_lights.size(), 1u);
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
