// Geometry of 3-D mortar segments on bilinear quadrilateral faces (Popp,
// Gee and Wall, IJNME 79 (2009); Puso and Laursen 2004): both faces of a
// pair are projected along the normal of an auxiliary plane, the projected
// primary face is clipped against the projected secondary face, and the
// clip polygon is cut into triangles for Gauss quadrature. Templated on the
// number type like the 2-D geometry (mortar_geometry.h): the decisions
// (which vertex lies inside, which points merge) are taken on the values,
// the coordinates carry derivatives, so that Sacado differentiates the
// segment through the normals, the projections and the clip vertices.
//
// A face's nodes are numbered as deal.II numbers a quadrilateral's
// vertices (lexicographic: (0,0), (1,0), (0,1), (1,1) in the reference
// square [0,1]^2), its shape functions are the bilinear N_0..N_3.
//
// The pieces, in the order they build on each other: face_geometry_3d.h
// (the faces), auxiliary_plane.h (projection onto the plane, clipping,
// triangles), face_projection_3d.h (triangle rules, projection along a
// direction), dual_basis_3d.h and segment_integrals_3d.h (a segment's
// quadrature points and integrals).
#ifndef contact_dynamics_contact_clipping_geometry_h
#define contact_dynamics_contact_clipping_geometry_h

#include <contact_dynamics/contact/auxiliary_plane.h>
#include <contact_dynamics/contact/dual_basis_3d.h>
#include <contact_dynamics/contact/face_geometry_3d.h>
#include <contact_dynamics/contact/face_projection_3d.h>
#include <contact_dynamics/contact/segment_integrals_3d.h>

#endif
