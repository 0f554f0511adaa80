// A contact surface of a 2-D or 3-D mesh: its nodes, faces (segments or
// bilinear quadrilaterals; with elements of degree 2 also their 3-node and
// 9-node forms) and degrees of freedom, and its current coordinates.
// Shared by the formulations.
#ifndef contact_dynamics_contact_contact_surface_h
#define contact_dynamics_contact_contact_surface_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/point.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class Mapping;
}

namespace ContactDynamics
{
  using namespace dealii;

  template <int dim>
  class ContactSurface
  {
  public:
    static constexpr unsigned int invalid = static_cast<unsigned int>(-1);

    static constexpr unsigned int nodes_per_face =
      GeometryInfo<dim>::vertices_per_face;

    /**
     * Collects the boundary faces with the given ids. Faces are oriented
     * so that the outward normal is, in 2-D, the tangent x1 - x0 turned
     * clockwise, in 3-D (x1 - x0) x (x2 - x0) (nodes numbered
     * lexicographically, as deal.II numbers a quadrilateral's vertices).
     * `n_node_components` degrees of freedom are recorded per node: the
     * displacement first, then any multiplier components. With elements of
     * degree 2 every node of a face is a surface node (the mid-side nodes,
     * in 3-D the centres too), placed by `mapping` (of degree 2; null: a
     * MappingQ(2) on the scene's manifolds).
     */
    void
    build(const DoFHandler<dim>                 &dof_handler,
          const std::vector<types::boundary_id> &boundary_ids,
          const unsigned int                     n_node_components,
          const Mapping<dim, dim>               *mapping = nullptr);

    unsigned int
    n_nodes() const
    {
      return reference.size();
    }

    unsigned int
    n_faces() const
    {
      return faces.size();
    }

    /** Current position x = X + u of a node. */
    Point<dim>
    position(const unsigned int                   node,
             const TrilinosWrappers::MPI::Vector &u) const
    {
      Point<dim> x = reference[node];
      for (unsigned int d = 0; d < dim; ++d)
        x[d] += u(dofs[node][d]);
      return x;
    }

    /**
     * Bounding box of a face in the configuration u, and its size (the
     * length in 2-D, the longer diagonal in 3-D).
     */
    BoundingBox<dim>
    face_box(const unsigned int                   face,
             const TrilinosWrappers::MPI::Vector &u,
             double                              &length) const
    {
      std::array<Point<dim>, nodes_per_face> x;
      for (unsigned int v = 0; v < nodes_per_face; ++v)
        x[v] = position(faces[face][v], u);
      BoundingBox<dim> box(std::make_pair(x[0], x[0]));
      for (unsigned int v = 1; v < face_nodes[face].size(); ++v)
        {
          const Point<dim> y =
            v < nodes_per_face ? x[v] : position(face_nodes[face][v], u);
          box.merge_with(BoundingBox<dim>(std::make_pair(y, y)));
        }
      length = x[0].distance(x[nodes_per_face - 1]);
      if constexpr (dim == 3)
        length = std::max(length, x[1].distance(x[2]));
      return box;
    }

    /**
     * 2-D: the other node of the face at `node` that is not `face`, or
     * invalid.
     */
    unsigned int
    neighbour(const unsigned int node, const unsigned int face) const;

    /**
     * Degree 2: the integral of a node's shape function over its faces in
     * the configuration u (reference_weight in the reference one).
     */
    double
    current_weight(const unsigned int                   node,
                   const TrilinosWrappers::MPI::Vector &u) const;

    unsigned int degree = 1; // of the faces' shape functions

    std::vector<Point<dim>> reference; // node positions
    std::vector<std::vector<types::global_dof_index>>     dofs;  // per node
    std::vector<std::array<unsigned int, nodes_per_face>> faces; // vertices
    // every node of a face: its vertices (faces[f]), then with degree 2 the
    // others in the order of QuadraticFace::node_coordinates()
    std::vector<std::vector<unsigned int>> face_nodes;
    std::vector<std::vector<unsigned int>> node_faces;
    std::vector<double>                    reference_weight; // integral N_j
    // per face: measure of its cell / measure of the face (reference), the
    // element's extent normal to the face
    std::vector<double> depth;
  };
} // namespace ContactDynamics

#endif
