#pragma once
// Physical constants (SI).

namespace centrec::thermal {

constexpr double kStefanBoltzmann = 5.670374419e-8;  // W/(m2 K4)

}  // namespace centrec::thermal
