#pragma once
// Numeric constants shared by the whole renderer.
#include <limits>

namespace femto {

inline constexpr float Pi = 3.14159265358979323846f;
inline constexpr float InvPi = 0.31830988618379067154f;
inline constexpr float Inv2Pi = 0.15915494309189533577f;
inline constexpr float Inv4Pi = 0.07957747154594766788f;
inline constexpr float Infinity = std::numeric_limits<float>::infinity();
// Offset used to leave a surface without re-hitting it (relative to scene scale 1).
inline constexpr float RayEpsilon = 1e-4f;
// Shadow rays stop this fraction short of their target.
inline constexpr float ShadowEpsilon = 1e-4f;

inline constexpr float degToRad(float deg) { return deg * (Pi / 180.0f); }
inline constexpr float radToDeg(float rad) { return rad * (180.0f / Pi); }

}  // namespace femto
