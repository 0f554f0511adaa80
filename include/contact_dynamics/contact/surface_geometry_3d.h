// Normals and tangents of 3-D contact surfaces (bilinear quadrilateral
// faces), templated on the number type, shared by the 3-D mortar and
// node-to-segment formulations.
#ifndef contact_dynamics_contact_surface_geometry_3d_h
#define contact_dynamics_contact_surface_geometry_3d_h

#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/clipping_geometry.h>
#include <contact_dynamics/contact/contact_surface.h>
#include <contact_dynamics/contact/quadratic_face.h>

#include <algorithm>
#include <map>
#include <vector>

namespace ContactDynamics
{
  namespace ClippingGeometry
  {
    using Surface = ContactSurface<3>;

    /** Node positions (or velocities) by surface node. */
    template <typename Number>
    using NodeMap = std::map<unsigned int, Vec3<Number>>;

    /** The four nodes of a face, from a node map. */
    template <typename Number>
    std::array<Vec3<Number>, 4>
    face_nodes(const Surface         &surface,
               const unsigned int     face,
               const NodeMap<Number> &x)
    {
      std::array<Vec3<Number>, 4> result;
      for (unsigned int a = 0; a < 4; ++a)
        result[a] = x.at(surface.faces[face][a]);
      return result;
    }

    /** The unit normal of the curved face f of degree 2 at its node a. */
    template <typename Number>
    Vec3<Number>
    quadratic_node_normal(const Surface         &s,
                          const unsigned int     f,
                          const unsigned int     a,
                          const NodeMap<Number> &xs)
    {
      const auto   q = QuadraticFace::node_coordinates<3>()[a];
      const auto   G = QuadraticFace::quad_shape_gradients(q[0], q[1]);
      Vec3<Number> t0, t1;
      for (unsigned int k = 0; k < 9; ++k)
        {
          const auto &x = xs.at(s.face_nodes[f][k]);
          t0 += Number(G[0][k]) * x;
          t1 += Number(G[1][k]) * x;
        }
      const Vec3<Number> n = cross(t0, t1);
      return n / norm(n);
    }

    /**
     * The average of the unit corner normals of the faces at a node (xs
     * holds the nodes of those faces: face_nodes). With degree 2 the
     * normals of the curved faces at the node.
     */
    template <typename Number>
    Vec3<Number>
    nodal_normal(const Surface         &s,
                 const unsigned int     node,
                 const NodeMap<Number> &xs)
    {
      std::vector<Vec3<Number>> corners;
      for (const unsigned int f : s.node_faces[node])
        {
          const auto &nodes = s.face_nodes[f];
          const auto  a =
            std::find(nodes.begin(), nodes.end(), node) - nodes.begin();
          corners.push_back(s.degree == 1 ?
                              corner_normal(face_nodes(s, f, xs), a) :
                              quadratic_node_normal(s, f, a, xs));
        }
      return averaged_normal(corners);
    }

    // The tangents t_1 = (a - (a.n) n) / |a - (a.n) n| and t_2 = n x t_1 of
    // a unit normal n, a the coordinate axis `axis`
    template <typename Number>
    std::array<Vec3<Number>, 2>
    tangent_basis(const Vec3<Number> &n, const unsigned int axis)
    {
      Vec3<Number> t;
      t[axis] = 1.;
      t -= Number(t * n) * n;
      // (|t| starts at 0.82 or more: below 0.3 the normal has turned to
      // within 17 degrees of the axis and the basis is ill-conditioned)
      AssertThrow(value_of(norm(t)) > 0.3,
                  dealii::ExcMessage(
                    "3-D friction: the contact normal at a secondary node "
                    "has turned by more than about 37 degrees from the "
                    "reference normal its tangents are built from, towards "
                    "their axis (doc/contact.md, '3-D friction'); tangent "
                    "bases that follow large rotations are not implemented "
                    "yet."));
      t /= norm(t);
      return {{t, cross(n, t)}};
    }

    // The axis least aligned with a node's nodal normal in the reference
    // configuration: its tangents (tangent_basis()) are smooth in the normal
    // while it turns by less than 37 degrees (it starts 54.7 or more away
    // from the axis)
    inline unsigned int
    tangent_axis(const Surface &s, const unsigned int node)
    {
      NodeMap<double> x;
      for (const unsigned int f : s.node_faces[node])
        for (const unsigned int k : s.face_nodes[f])
          x[k] = s.reference[k];
      const auto   n    = nodal_normal(s, node, x);
      unsigned int axis = 0;
      for (unsigned int d = 1; d < 3; ++d)
        if (std::abs(n[d]) < std::abs(n[axis]))
          axis = d;
      return axis;
    }
  } // namespace ClippingGeometry
} // namespace ContactDynamics

#endif
