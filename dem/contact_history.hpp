#pragma once
// History of one contact (docs/dem_physics.md): the Mindlin tangential spring and the
// EPSD2 rolling spring. All zero means "not in contact".
#include "dem/vec3.hpp"

namespace centrec::dem {

struct ContactHistory {
  Vec3 shear;  // accumulated tangential displacement, m (Ft = -kt shear)
  Vec3 roll;   // EPSD2 rolling-spring torque Mr, N m (torque -Mr on i, +Mr on j)
};
// Units of a history stored as six numbers (shear x y z, roll x y z).
inline constexpr const char* kContactHistoryUnits = "m (shear 0-2), N m (roll 3-5)";

inline bool is_zero(const ContactHistory& h) {
  return h.shear.x == 0.0 && h.shear.y == 0.0 && h.shear.z == 0.0 && h.roll.x == 0.0 && h.roll.y == 0.0 &&
         h.roll.z == 0.0;
}

}  // namespace centrec::dem
