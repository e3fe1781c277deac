#pragma once
// ASCII STL of the drum's cylinder wall for LIGGGHTS' fix mesh/surface.
#include <string>

namespace centrec::bench {

// Inscribed polygonal cylinder about the z axis: `around` facet columns (vertices on the
// radius, so a facet's middle lies R (1 - cos(pi/around)) inside), `axial` segments over
// z in [0, length], two triangles per quad, normals pointing inwards.
// Returns the triangle count.
long write_cylinder_stl(const std::string& path, double radius, double length, int around, int axial);

}  // namespace centrec::bench
