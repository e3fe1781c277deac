#pragma once
// A drum's developed film: the axial window, as fractions of the drum length, that leaves
// out the feeder's inflow and the outlet's outflow. The solid-fraction and dispersion
// samplers average there (docs/film_sampling.md) and the coupling maps the sections there
// (docs/coupling.md "Film as measured"). A periodic slice is developed everywhere.
namespace centrec::film {

constexpr double kDevelopedFrom = 0.2, kDevelopedTo = 0.8;

}  // namespace centrec::film
