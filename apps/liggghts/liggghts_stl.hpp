#pragma once
// ASCII STL surfaces for LIGGGHTS' fix mesh/surface, written from the analytic drum
// geometry (axis +z): the cylinder wall, flat annuli/discs (back plate, outlet lip,
// outlet counting face). One writer for the application and the benchmark.
#include <ostream>
#include <string>

namespace centrec::liggghts {

// Inscribed polygonal cylinder about the z axis: `around` facet columns (vertices on the
// radius, so a facet's middle lies R (1 - cos(pi/around)) inside), `axial` segments over
// z in [z0, z1], two triangles per quad, normals pointing to the axis. Returns triangles.
long write_cylinder_facets(std::ostream& out, double radius, double z0, double z1, int around, int axial);

// Flat annulus r_in <= r <= r_out in the plane z (r_in = 0: a disc, fanned from the
// centre) with `around` sectors; normals along +z if `normal_up`, else -z. Returns triangles.
long write_annulus_facets(std::ostream& out, double z, double r_in, double r_out, int around, bool normal_up);

// Facet columns for a cylinder of `radius` so its facets lie within `sagitta` of the
// true surface (at least 24).
int facets_around(double radius, double sagitta);

// Axial segments for a cylinder of `around` facet columns so its facets are about 10 times
// longer than wide (as fast as full-length ones in LIGGGHTS, which refuses much longer ones).
int facets_along(double radius, double length, int around);

// The `curvature` (degrees) to give fix mesh/surface for a cylinder written by
// write_cylinder_facets: LIGGGHTS copies a contact's history (tangential and rolling
// springs) to the next triangle only if the two lie within `curvature` of each other, and
// its default (0.256 deg) is below the turn between neighbouring facet columns (360/around
// deg), so a particle riding the drum round would lose its wall history at every column
// and slip as if the wall had no memory. Returns the midpoint between that turn and the
// smallest angle inside a triangle (LIGGGHTS refuses a curvature above it); throws
// std::invalid_argument if the facets are too slender to separate the two.
double cylinder_curvature_deg(double radius, double length, int around, int axial);

// A whole STL file holding one cylinder (the benchmark's drum wall).
long write_cylinder_stl(const std::string& path, double radius, double length, int around, int axial);

}  // namespace centrec::liggghts
