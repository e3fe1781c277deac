#include "particle_arrays.hpp"

#include <stdexcept>
#include <string>

namespace centrec::film {

void require_arrays(const ParticleArrays& p, const char* needs, const char* who) {
  if (p.count == 0) return;
  for (const char* c = needs; *c; ++c) {
    const void* ptr = nullptr;
    const char* name = "?";
    switch (*c) {
      case 'x': ptr = p.x; name = "x"; break;
      case 'y': ptr = p.y; name = "y"; break;
      case 'z': ptr = p.z; name = "z"; break;
      case 'v': ptr = p.vz; name = "vz"; break;
      case 'r': ptr = p.radius; name = "radius"; break;
      case 'i': ptr = p.id; name = "id"; break;
      default: throw std::logic_error(std::string(who) + ": unknown array letter");
    }
    if (!ptr) throw std::invalid_argument(std::string(who) + ": particle array '" + name + "' is null");
  }
}

ParticleArrays ParticleColumns::view() const {
  ParticleArrays v;
  v.count = x.size();
  v.x = x.data();
  v.y = y.data();
  v.z = z.data();
  v.vx = vx.data();
  v.vy = vy.data();
  v.vz = vz.data();
  v.radius = radius.data();
  v.id = id.data();
  v.time = time;
  return v;
}

}  // namespace centrec::film
