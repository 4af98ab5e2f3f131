#include "safegi/cpu_renderer/rigid_motion.hpp"

#include <algorithm>
#include <cmath>

namespace safegi::render {

namespace kernel {

Affine inverse(const Affine& a) {
  const auto& m = a.m;
  Real c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  Real c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  Real c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  Real det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  Real s = 1.0f / det;
  Affine r;
  r.m[0][0] = c00 * s;
  r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * s;
  r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * s;
  r.m[1][0] = c01 * s;
  r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * s;
  r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * s;
  r.m[2][0] = c02 * s;
  r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * s;
  r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * s;
  Real3 t = r.apply_vector(column(a, 3));
  r.m[0][3] = -t.x;
  r.m[1][3] = -t.y;
  r.m[2][3] = -t.z;
  return r;
}

Affine Affine::from(const RenderFromObject& map) {
  sg::mat4_rep forward = sg::raw(map).forward;  // column-major
  Affine a;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) a.m[r][c] = forward[c][r];
  return a;
}

}  // namespace kernel

using kernel::column;
using kernel::Real3;
using kernel::inverse;

RigidMotion::Pose RigidMotion::decompose(const Affine& m) {
  Pose pose;
  pose.translation = column(m, 3);
  // Polar decomposition M = R S by averaging R with its inverse transpose.
  Affine rotation = m;
  for (int r = 0; r < 3; ++r) rotation.m[r][3] = 0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    Affine inv = inverse(rotation);
    Affine next;
    Real change = 0;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        next.m[r][c] = 0.5f * (rotation.m[r][c] + inv.m[c][r]);
        change = std::fmax(change, std::fabs(next.m[r][c] - rotation.m[r][c]));
      }
    rotation = next;
    if (change < 1e-7f) break;
  }
  Affine scale = inverse(rotation) * m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) pose.scale[r][c] = scale.m[r][c];
  // Rotation matrix to quaternion.
  const auto& R = rotation.m;
  Real trace = R[0][0] + R[1][1] + R[2][2];
  Real* q = pose.rotation;
  if (trace > 0) {
    Real s = std::sqrt(trace + 1.0f) * 2;
    q[3] = 0.25f * s;
    q[0] = (R[2][1] - R[1][2]) / s;
    q[1] = (R[0][2] - R[2][0]) / s;
    q[2] = (R[1][0] - R[0][1]) / s;
  } else if (R[0][0] > R[1][1] && R[0][0] > R[2][2]) {
    Real s = std::sqrt(1.0f + R[0][0] - R[1][1] - R[2][2]) * 2;
    q[3] = (R[2][1] - R[1][2]) / s;
    q[0] = 0.25f * s;
    q[1] = (R[0][1] + R[1][0]) / s;
    q[2] = (R[0][2] + R[2][0]) / s;
  } else if (R[1][1] > R[2][2]) {
    Real s = std::sqrt(1.0f + R[1][1] - R[0][0] - R[2][2]) * 2;
    q[3] = (R[0][2] - R[2][0]) / s;
    q[0] = (R[0][1] + R[1][0]) / s;
    q[1] = 0.25f * s;
    q[2] = (R[1][2] + R[2][1]) / s;
  } else {
    Real s = std::sqrt(1.0f + R[2][2] - R[0][0] - R[1][1]) * 2;
    q[3] = (R[1][0] - R[0][1]) / s;
    q[0] = (R[0][2] + R[2][0]) / s;
    q[1] = (R[1][2] + R[2][1]) / s;
    q[2] = 0.25f * s;
  }
  return pose;
}

RigidMotion::RigidMotion(const Affine& at_open, const Affine& at_close, Real time_open, Real time_close)
    : open_(decompose(at_open)), close_(decompose(at_close)), time_open_(time_open), time_close_(time_close) {
  // Take the shorter arc.
  Real d = 0;
  for (int i = 0; i < 4; ++i) d += open_.rotation[i] * close_.rotation[i];
  if (d < 0)
    for (Real& c : close_.rotation) c = -c;
}

Affine RigidMotion::at(Real time) const {
  Real span = time_close_ - time_open_;
  Real s = span > 0 ? std::clamp((time - time_open_) / span, Real(0), Real(1)) : Real(0);
  Real3 translation = open_.translation * (1 - s) + close_.translation * s;
  // Slerp, falling back to a normalised lerp for nearly equal rotations.
  Real cos_theta = 0;
  for (int i = 0; i < 4; ++i) cos_theta += open_.rotation[i] * close_.rotation[i];
  Real q[4];
  if (cos_theta > 0.9995f) {
    Real norm = 0;
    for (int i = 0; i < 4; ++i) {
      q[i] = open_.rotation[i] * (1 - s) + close_.rotation[i] * s;
      norm += q[i] * q[i];
    }
    for (Real& c : q) c /= std::sqrt(norm);
  } else {
    Real theta = std::acos(std::clamp(cos_theta, Real(-1), Real(1)));
    Real a = std::sin((1 - s) * theta) / std::sin(theta), b = std::sin(s * theta) / std::sin(theta);
    for (int i = 0; i < 4; ++i) q[i] = open_.rotation[i] * a + close_.rotation[i] * b;
  }
  Real x = q[0], y = q[1], z = q[2], w = q[3];
  Affine rotation;
  rotation.m[0][0] = 1 - 2 * (y * y + z * z);
  rotation.m[0][1] = 2 * (x * y - z * w);
  rotation.m[0][2] = 2 * (x * z + y * w);
  rotation.m[1][0] = 2 * (x * y + z * w);
  rotation.m[1][1] = 1 - 2 * (x * x + z * z);
  rotation.m[1][2] = 2 * (y * z - x * w);
  rotation.m[2][0] = 2 * (x * z - y * w);
  rotation.m[2][1] = 2 * (y * z + x * w);
  rotation.m[2][2] = 1 - 2 * (x * x + y * y);
  Affine scale;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) scale.m[r][c] = open_.scale[r][c] * (1 - s) + close_.scale[r][c] * s;
  Affine result = rotation * scale;
  for (int r = 0; r < 3; ++r) result.m[r][3] = translation[r];
  return result;
}

RenderFromObject RigidMotion::render_from_object(Time time) const {
  Affine affine = at(sg::raw(time));
  sg::mat4_rep forward(Real(1));
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) forward[c][r] = affine.m[r][c];
  return sg::from_raw<RenderFromObject>({forward, glm::inverse(forward)});
}

std::optional<RigidMotion> motion_of(const Shape& shape, const Camera& camera) {
  if (!(camera.shutter_close > camera.shutter_open) || !shape.render_from_object_at_close) return std::nullopt;
  return RigidMotion(Affine::from(shape.render_from_object), Affine::from(*shape.render_from_object_at_close),
                     sg::raw(camera.shutter_open), sg::raw(camera.shutter_close));
}

Real area_scale(const Affine& m, Real3 normal_after) {
  Real3 c0 = column(m, 0), c1 = column(m, 1), c2 = column(m, 2);
  Real determinant = kernel::dot(c0, kernel::cross(c1, c2));
  Real3 transposed{kernel::dot(c0, normal_after), kernel::dot(c1, normal_after), kernel::dot(c2, normal_after)};
  return std::fabs(determinant) / kernel::length(transposed);
}

}  // namespace safegi::render
