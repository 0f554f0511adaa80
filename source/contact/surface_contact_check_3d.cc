// The 3-D passage of a secondary node through a bilinear primary face: the
// depth behind the face at the end of the step of a node that was in front
// of it at the start.
#include <contact_dynamics/contact/closest_point_3d.h>
#include <contact_dynamics/contact/coordinates.h>
#include <contact_dynamics/contact/face_passage.h>
#include <contact_dynamics/contact/surface_geometry_3d.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace ContactDynamics
{
  namespace
  {
    std::array<ClippingGeometry::Vec3<double>, 4>
    face_nodes(const ContactSurface<3> &surface,
               const unsigned int       face,
               const VectorType        &u)
    {
      std::array<ClippingGeometry::Vec3<double>, 4> x;
      for (unsigned int a = 0; a < 4; ++a)
        x[a] = surface.position(surface.faces[face][a], u);
      return x;
    }

    Point<3>
    face_center(const ContactSurface<3> &surface,
                const unsigned int       face,
                const VectorType        &u)
    {
      return Point<3>(
        ClippingGeometry::interpolate(face_nodes(surface, face, u), 0.5, 0.5));
    }

    // x's distance in front of the bilinear face (along its normal at the
    // closest point), NaN if x does not project onto the face
    double
    distance_in_front(const std::array<ClippingGeometry::Vec3<double>, 4> &x,
                      const Point<3>                                      &p)
    {
      using namespace ClippingGeometry;
      double       xi, eta;
      const double margin = 1e-10;
      if (!closest_point(x, p, xi, eta) || xi < -margin || eta < -margin ||
          xi > 1 + margin || eta > 1 + margin)
        return std::numeric_limits<double>::quiet_NaN();
      const auto   t = tangents(x, xi, eta);
      Vec3<double> n = ClippingGeometry::cross(t[0], t[1]);
      n /= norm(n);
      return (p - interpolate(x, xi, eta)) * n;
    }

    // 3-D: how far the point x1 (x0 at the last step) lies behind the
    // bilinear face at the state u (committed_u), if it projects onto the
    // face at both states and was in front of it before; else 0. (The
    // states at the ends of the step, not the swept path of 2-D.)
    double
    depth_behind_face(const ContactSurface<3> &surface,
                      const unsigned int       face,
                      const Point<3>          &x0,
                      const Point<3>          &x1,
                      const VectorType        &committed_u,
                      const VectorType        &u)
    {
      double signed_distance[2];
      for (unsigned int k = 0; k < 2; ++k)
        {
          signed_distance[k] = distance_in_front(
            face_nodes(surface, face, k == 0 ? committed_u : u),
            k == 0 ? x0 : x1);
          if (std::isnan(signed_distance[k]))
            return 0;
        }
      return signed_distance[0] >= 0 && signed_distance[1] < 0 ?
               -signed_distance[1] :
               0.;
    }
  } // namespace

  std::string
  passage_through_face(const ContactSurface<3>      &f,
                       const std::set<unsigned int> &faces,
                       const Point<3>               &x0,
                       const Point<3>               &x1,
                       const VectorType             &committed_u,
                       const VectorType             &u,
                       const double                  tolerance)
  {
    for (const unsigned int e : faces)
      if (const double depth = depth_behind_face(f, e, x0, x1, committed_u, u);
          depth > std::max(tolerance, 1e-2 * f.depth[e]))
        {
          std::ostringstream passage;
          passage << "went through the primary face with center "
                  << coordinates(face_center(f, e, u))
                  << " in this step and ends " << depth
                  << " behind it, but its contact condition is not active";
          return passage.str();
        }
    return {};
  }



  Tensor<1, 3>
  outward_normal(const ContactSurface<3> &surface,
                 const unsigned int       node,
                 const VectorType        &u)
  {
    ClippingGeometry::NodeMap<double> x;
    for (const unsigned int f : surface.node_faces[node])
      for (const unsigned int k : surface.face_nodes[f])
        x[k] = surface.position(k, u);
    const auto   n = ClippingGeometry::nodal_normal(surface, node, x);
    Tensor<1, 3> result;
    for (unsigned int d = 0; d < 3; ++d)
      result[d] = n[d];
    return result;
  }

  double
  depth_behind_surface(const ContactSurface<3>      &surface,
                       const std::set<unsigned int> &faces,
                       const Point<3>               &x,
                       const VectorType             &u)
  {
    double signed_distance = std::numeric_limits<double>::quiet_NaN();
    for (const unsigned int e : faces)
      {
        const double d = distance_in_front(face_nodes(surface, e, u), x);
        if (!std::isnan(d) && !(std::abs(d) >= std::abs(signed_distance)))
          signed_distance = d;
      }
    return -signed_distance;
  }
} // namespace ContactDynamics
