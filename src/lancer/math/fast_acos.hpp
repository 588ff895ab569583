// acos in float without a library call, within a few float ulps of the true angle: the corner
// angles that weight vertex normals take three or four of these per face, and libm's acosf (a call
// per angle, its error handling) was the largest single cost of computing the normals of a big mesh.
// Cephes' asinf polynomial (max relative error about 2.5e-7 on [0, 0.5]), with acos(x) = pi/2 -
// asin(x) for |x| <= 0.5 and acos(x) = 2 asin(sqrt((1 - x) / 2)) above (exact identities).
#pragma once

#include <cmath>

namespace lancer {

// x in [-1, 1] (clamp first); the angle in [0, pi].
inline float fastAcos(float x) {
  const float a = std::fabs(x);
  const bool wide = a > 0.5f;
  const float z = wide ? 0.5f * (1.0f - a) : a * a;
  const float s = wide ? std::sqrt(z) : a;
  const float asinS =
      ((((4.2163199048e-2f * z + 2.4181311049e-2f) * z + 4.5470025998e-2f) * z + 7.4953002686e-2f) * z +
       1.6666752422e-1f) *
          z * s +
      s;
  const float acosA = wide ? 2.0f * asinS : 1.5707963267948966f - asinS;
  return x < 0.0f ? 3.14159265358979f - acosA : acosA;
}

}  // namespace lancer
