// A contact surface of a 2-D mesh: its nodes, faces and degrees of
// freedom, and its current coordinates. Shared by the formulations.
#ifndef contact_dynamics_contact_contact_surface_h
#define contact_dynamics_contact_contact_surface_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  template <int dim>
  class ContactSurface
  {
  public:
    static constexpr unsigned int invalid = static_cast<unsigned int>(-1);

    /**
     * Collects the boundary faces with the given ids. Faces are oriented
     * so that the outward normal is the tangent x1 - x0 turned clockwise.
     * `n_node_components` degrees of freedom are recorded per node: the
     * displacement first, then any multiplier components.
     */
    void
    build(const DoFHandler<dim>                 &dof_handler,
          const std::vector<types::boundary_id> &boundary_ids,
          const unsigned int                     n_node_components);

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

    /** Bounding box of a face in the configuration u, and its length. */
    BoundingBox<dim>
    face_box(const unsigned int                   face,
             const TrilinosWrappers::MPI::Vector &u,
             double                              &length) const
    {
      const Point<dim> a = position(faces[face][0], u);
      const Point<dim> b = position(faces[face][1], u);
      BoundingBox<dim> box(std::make_pair(a, a));
      box.merge_with(BoundingBox<dim>(std::make_pair(b, b)));
      length = a.distance(b);
      return box;
    }

    /** The other node of the face at `node` that is not `face`, or invalid. */
    unsigned int
    neighbour(const unsigned int node, const unsigned int face) const;

    std::vector<Point<dim>> reference;                       // node positions
    std::vector<std::vector<types::global_dof_index>> dofs;  // per node
    std::vector<std::array<unsigned int, 2>>          faces; // node indices
    std::vector<std::vector<unsigned int>>            node_faces;
    std::vector<double> reference_weight; // integral N_j
    // per face: area of its cell / face length (reference), the element's
    // extent normal to the face
    std::vector<double> depth;
  };
} // namespace ContactDynamics

#endif
