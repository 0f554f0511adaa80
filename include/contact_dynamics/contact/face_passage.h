// SurfaceContact::check_step() per dimension (surface_contact_check_2d.cc,
// _3d.cc): how a secondary node that moved from x0 to x1 in a step went
// through one of the given faces of a primary surface (moving from their
// positions at committed_u to those at u) and ends deeper than the tolerance
// behind it; empty if it did not. And the outward unit normal of a
// surface at a node (the mean of its faces' normals) in the configuration u.
// And how deep a point x lies behind the nearest of the faces it projects
// onto (negative: in front), or NaN if it projects onto none.
#ifndef contact_dynamics_contact_face_passage_h
#define contact_dynamics_contact_face_passage_h

#include <contact_dynamics/contact/contact_surface.h>

#include <set>
#include <string>

namespace ContactDynamics
{
  using VectorType = TrilinosWrappers::MPI::Vector;

  std::string
  passage_through_face(const ContactSurface<2>      &primary,
                       const std::set<unsigned int> &faces,
                       const Point<2>               &x0,
                       const Point<2>               &x1,
                       const VectorType             &committed_u,
                       const VectorType             &u,
                       const double                  tolerance);

  std::string
  passage_through_face(const ContactSurface<3>      &primary,
                       const std::set<unsigned int> &faces,
                       const Point<3>               &x0,
                       const Point<3>               &x1,
                       const VectorType             &committed_u,
                       const VectorType             &u,
                       const double                  tolerance);

  Tensor<1, 2>
  outward_normal(const ContactSurface<2> &surface,
                 const unsigned int       node,
                 const VectorType        &u);

  double
  depth_behind_surface(const ContactSurface<2>      &surface,
                       const std::set<unsigned int> &faces,
                       const Point<2>               &x,
                       const VectorType             &u);

  Tensor<1, 3>
  outward_normal(const ContactSurface<3> &surface,
                 const unsigned int       node,
                 const VectorType        &u);

  double
  depth_behind_surface(const ContactSurface<3>      &surface,
                       const std::set<unsigned int> &faces,
                       const Point<3>               &x,
                       const VectorType             &u);
} // namespace ContactDynamics

#endif
