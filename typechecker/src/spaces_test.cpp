// Space analysis: affine rules, maps, normals, directions, projective maps.

#include <gtest/gtest.h>

#include <algorithm>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

using Messages = std::vector<std::string>;

constexpr const char* kGlobals =
    "space world; space object; space clip;\n"
    "uniform map<object, world> worldFromObject;\n"
    "uniform rigidmap<object, world> rigidWorldFromObject;\n"
    "uniform projmap<world, clip> clipFromWorld;\n"
    "uniform point<world> pw; uniform point<object> po;\n"
    "uniform vector<world> vw; uniform normal<object> no; uniform direction<world> dw;\n";

Messages messages_of(std::string_view body) {
  return check_source(std::string(kGlobals) + "void main() {\n" + std::string(body) + "\n}\n")->messages();
}

TEST(Spaces, AffineRules) {
  EXPECT_EQ(messages_of("vector<world> v = pw - pw; point<world> p = pw + v; p = p - v; vector<world> w = v + v;"), Messages{});
  EXPECT_EQ(messages_of("point<world> p = pw + pw;"), Messages{"error: cannot add two points (point<world> and point<world>)"});
  EXPECT_EQ(messages_of("point<world> p = pw * 2.0;"),
            Messages{"error: cannot multiply point<world> and float<dimensionless>: a point cannot be scaled"});
  EXPECT_EQ(messages_of("vector<world> v = vw - pw;"), Messages{"error: cannot subtract a point from vector<world>"});
}

TEST(Spaces, OperandsMustShareASpace) {
  EXPECT_EQ(messages_of("vector<world> v = pw - po;"),
            Messages{"error: cannot subtract point<world> and point<object>: they are in different spaces"});
  auto c = check_source(std::string(kGlobals) + "void main() { vector<world> v = pw - po; }");
  ASSERT_EQ(c->diagnostics.diagnostics().size(), 1u);
  EXPECT_EQ(c->diagnostics.diagnostics()[0].hint, "missing transform by map<object, world>?");
}

TEST(Spaces, MapsChangeSpaces) {
  EXPECT_EQ(messages_of("point<world> p = worldFromObject * po; point<world> q = transform(worldFromObject, po);"
                        "normal<world> n = worldFromObject * no; hpoint<clip> h = clipFromWorld * pw;"
                        "point<clip> back = homogenize(project(clipFromWorld, pw));"
                        "map<world, object> inv = inverse(worldFromObject);"
                        "projmap<object, clip> full = clipFromWorld * worldFromObject;"),
            Messages{});
  EXPECT_EQ(messages_of("point<world> p = worldFromObject * pw;"),
            Messages{"error: cannot apply map<object, world> to point<world>: the map takes values in object"});
  EXPECT_EQ(messages_of("map<object, clip> m = worldFromObject * clipFromWorld;"),
            Messages{"error: cannot compose map<object, world> with projmap<world, clip>: the projective map gives homogeneous "
                     "points, which a map does not take"});
  EXPECT_EQ(messages_of("map<object, object> m = worldFromObject * worldFromObject;"),
            Messages{"error: cannot compose map<object, world> with map<object, world>: the right-hand map ends in world but "
                     "the left-hand one starts in object"});
  EXPECT_EQ(messages_of("point<object> p = worldFromObject * po;"),
            Messages{"error: cannot initialize 'p' of type point<object> with a value of type point<world>"});
}

// The kind of a composition follows from its operands; a rigidmap is also a map.
TEST(Spaces, CompositionKindFollowsTheOperands) {
  const std::string globals = std::string(kGlobals) +
                              "space view;\n"
                              "uniform rigidmap<world, view> viewFromWorld;\n"
                              "uniform projmap<view, clip> clipFromView;\n"
                              "uniform projmap<clip, clip> jitter;\n";
  auto e = check_source(globals +
                        "void main() {\n"
                        "  projmap<object, clip> mvp = clipFromView * viewFromWorld * worldFromObject;\n"
                        "  map<object, view> mv = viewFromWorld * worldFromObject;\n"
                        "  rigidmap<object, view> rv = viewFromWorld * rigidWorldFromObject;\n"
                        "  projmap<object, clip> jittered = jitter * mvp;\n"
                        "  map<object, world> widened = rigidWorldFromObject;\n"
                        "  hpoint<clip> h = mvp * po;\n"
                        "}\n");
  ASSERT_EQ(e->messages(), Messages{});
  EXPECT_EQ(declared_type(*e, "mvp"), "projmap<object, clip>");
  EXPECT_EQ(declared_type(*e, "rv"), "rigidmap<object, view>");
  EXPECT_EQ(check_source(globals + "void main() { rigidmap<object, view> rv = viewFromWorld * worldFromObject; }")->messages(),
            Messages{"error: cannot initialize 'rv' of type rigidmap<object, view> with a value of type map<object, view>"});
  EXPECT_EQ(check_source(globals + "void main() { projmap<world, clip> p = viewFromWorld * clipFromView; }")->messages(),
            Messages{"error: cannot compose rigidmap<world, view> with projmap<view, clip>: the projective map gives "
                     "homogeneous points, which a rigidmap does not take"});
}

TEST(Spaces, NormalsThroughNonRigidMapsUseTheInverseTranspose) {
  auto c = check_source(std::string(kGlobals) + "void main() { normal<world> a = worldFromObject * no; normal<world> b = rigidWorldFromObject * no; }");
  ASSERT_EQ(c->rendered(), "");
  std::vector<GeometricOp> ops;
  for (const auto& [node, info] : c->result.calls) ops.push_back(info.op);
  std::sort(ops.begin(), ops.end());
  EXPECT_EQ(ops, (std::vector<GeometricOp>{GeometricOp::transform_vector, GeometricOp::transform_normal}));
}

TEST(Spaces, VectorToDirectionNeedsNormalize) {
  EXPECT_EQ(messages_of("direction<world> d = normalize(pw - pw);"), Messages{});
  auto c = check_source(std::string(kGlobals) + "void main() { direction<world> d = pw - pw; }");
  ASSERT_EQ(c->messages(), Messages{"error: cannot initialize 'd' of type direction<world> with a value of type vector<world>"});
  EXPECT_EQ(c->diagnostics.diagnostics()[0].hint, "a vector becomes a direction only through normalize()");
}

TEST(Spaces, DotAndCrossNeedOneSpace) {
  EXPECT_EQ(messages_of("float c = dot(dw, normalize(vw)); vector<world> x = cross(vw, dw);"), Messages{});
  EXPECT_EQ(messages_of("float<proj> c = dot(no, dw);"),
            Messages{"error: argument 2 of 'dot' has type direction<world>, but the other arguments are in object"});
}

TEST(Spaces, GenericSpaceFunctions) {
  const std::string globals = std::string(kGlobals) +
                              "template<space S> float<length> dist(point<S> a, point<S> b) { return length(a - b); }\n";
  EXPECT_EQ(check_source(globals + "void main() { float<length> d = dist(pw, pw); float<length> e = dist(po, po); }")->messages(),
            Messages{});
  EXPECT_EQ(check_source(globals + "void main() { float<length> d = dist(pw, po); }")->messages(),
            Messages{"error: argument 2 of 'dist' has type point<object>, but the other arguments are in world"});
}

// Only a difference of points is a vector: a point given to a vector operation is an error.
TEST(Spaces, PointsAreNotDirections) {
  EXPECT_EQ(messages_of("direction<world> d = normalize(pw);"),
            Messages{"error: cannot normalize point<world> 'pw': a point is a position, not a direction"});
  EXPECT_EQ(messages_of("float<length> d = length(pw);"),
            Messages{"error: cannot take the length of point<world> 'pw': a point is a position, and its length would "
                     "depend on where world's origin is"});
  EXPECT_EQ(messages_of("float x = dot(dw, pw);"),
            Messages{"error: 'dot' needs vectors, directions or normals, not point<world> 'pw': a point is a position"});
  EXPECT_EQ(messages_of("vec3 r = reflect(pw, dw);"),
            Messages{"error: 'reflect' needs vectors, directions or normals, not point<world> 'pw': a point is a position"});
  EXPECT_EQ(messages_of("vec3 r = cross(vw, pw);"),
            Messages{"error: 'cross' needs vectors, directions or normals, not point<world> 'pw': a point is a position"});
  // Differences of points, explicit position vectors and plain vec3 are fine.
  EXPECT_EQ(messages_of("direction<world> d = normalize(pw - pw); float<length> a = length(vector<world>(pw));"
                        "float<length> b = distance(pw, pw); vec3 n = normalize(vec3(1.0)); float c = dot(vec3(1.0), vec3(2.0));"),
            Messages{});
  // Component-wise built-ins keep a point's kind and space.
  auto c = check_source(std::string(kGlobals) + "void main() { point<world> mid = mix(pw, pw, 0.5); point<world> lo = min(pw, pw); }");
  ASSERT_EQ(c->messages(), Messages{});
  EXPECT_EQ(declared_type(*c, "mid"), "point<world>");
  EXPECT_EQ(messages_of("point<world> mid = mix(pw, po, 0.5);"),
            Messages{"error: argument 2 of 'mix' has type point<object>, but the other arguments are in world"});
}

// Swizzles of an hpoint stay homogeneous until divided by a w of the same point.
TEST(Spaces, HomogeneousCoordinatesNeedTheDivide) {
  const std::string globals = std::string(kGlobals) + "uniform sampler2D<float<length>> depthMap;\n";
  auto c = check_source(globals +
                        "void main() {\n"
                        "  hpoint<clip> h = clipFromWorld * pw;\n"
                        "  vec2 raw = h.xy * 0.5 + 0.5;\n"
                        "  vec2 uv = h.xy / h.w * 0.5 + 0.5;\n"
                        "  float invW = 1.0 / h.w;\n"
                        "  vec2 uv2 = h.xy * invW;\n"
                        "  point<clip> ndc = h.xyz / h[3];\n"
                        "  float<length> a = texture(depthMap, uv).r + texture(depthMap, uv2).r;\n"
                        "  vec4 b = textureProj(depthMap, h);\n"
                        "}\n");
  ASSERT_EQ(c->messages(), Messages{});
  EXPECT_EQ(declared_type(*c, "raw"), "vec2 of hpoint<clip>");
  EXPECT_EQ(declared_type(*c, "invW"), "float carrying w^-1 of hpoint<clip>");
  EXPECT_EQ(declared_type(*c, "uv"), "vec2");
  EXPECT_EQ(declared_type(*c, "ndc"), "point<clip>");
  EXPECT_EQ(check_source(globals + "void main() { hpoint<clip> h = clipFromWorld * pw;"
                                   " float<length> d = texture(depthMap, h.xy * 0.5 + 0.5).r; }")
                ->messages(),
            Messages{"error: texture coordinates of type vec2 of hpoint<clip> are homogeneous: the perspective divide by w "
                     "is missing"});
  EXPECT_EQ(check_source(globals + "void main() { hpoint<clip> h = clipFromWorld * pw; point<clip> p = h.xyz; }")->messages(),
            Messages{"error: cannot initialize 'p' of type point<clip> with a value of type vec3 of hpoint<clip>"});
}

// Found in Gator's microfacet benchmark: `t - dot(t, n)` meant `t - dot(t, n) * n`.
TEST(Spaces, ANumberAddedToEveryCoordinateIsAKindError) {
  EXPECT_EQ(messages_of("vector<world> t = vw - dot(vw, dw);"),
            Messages{"error: cannot subtract vector<world> and float<length>: a number added to every coordinate of a "
                     "vector depends on the axes of world"});
  EXPECT_EQ(messages_of("point<world> p = pw + 1.0 * meter;"),
            Messages{"error: cannot add point<world> and float<length>: a number added to every coordinate of a point "
                     "depends on the axes of world"});
  EXPECT_EQ(messages_of("vector<world> t = vw - dot(vw, dw) * dw; vec3 plain = vec3(1.0) + 0.5; vector<world> z = vw + 0.0;"),
            Messages{});
}

TEST(Spaces, ReflectKeepsKindAndSpace) {
  auto c = check_source(std::string(kGlobals) + "void main() { direction<world> r = reflect(dw, dw); vector<world> v = reflect(vw, dw); }");
  ASSERT_EQ(c->messages(), Messages{});
  EXPECT_EQ(messages_of("vec3 r = reflect(vw, no);"),
            Messages{"error: argument 2 of 'reflect' has type normal<object>, but the other arguments are in world"});
}

TEST(Spaces, PlainVec3IsConsistentWithEveryKind) {
  EXPECT_EQ(check_source(std::string(kGlobals) + "in vec3 raw; void main() { point<world> p = pw + raw; vector<world> v = raw; p = raw; }")
                ->messages(),
            Messages{});
  // A kind-less vec3 may be a point: plain - point is a vector.
  auto c = check_source(std::string(kGlobals) + "in vec3 raw; void main() { vector<world> v = raw - pw; }");
  ASSERT_EQ(c->messages(), Messages{});
}

}  // namespace
}  // namespace safegi::testing
