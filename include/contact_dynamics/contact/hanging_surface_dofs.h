// The hanging-node constraints of the contact surfaces' degrees of freedom
// on an adapted 3-D mesh, of all processes: a process computes patches of
// any part of a surface, so it must know where the forces, Jacobian columns
// and nodal sums of any hanging node go (to the nodes it follows).
#ifndef contact_dynamics_contact_hanging_surface_dofs_h
#define contact_dynamics_contact_hanging_surface_dofs_h

#include <deal.II/base/index_set.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <contact_dynamics/contact/contact_surface.h>

#include <array>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace ContactDynamics
{
  class HangingSurfaceDofs
  {
  public:
    /** The degrees of freedom a hanging one follows, with their weights. */
    using Followed = std::vector<std::pair<types::global_dof_index, double>>;

    /**
     * From the hanging-node constraints of the surface dofs, of every
     * process (collective); owned_dofs are this process's.
     */
    template <int dim>
    void
    collect(const DoFHandler<dim>                   &dof_handler,
            const std::set<types::global_dof_index> &surface,
            const IndexSet                          &owned_dofs);

    bool
    empty() const;

    /** What dof follows, or nullptr if it does not hang. */
    const Followed *
    find(const types::global_dof_index dof) const;

    /** Adds the constraints of the dofs not constrained yet. */
    void
    add_constraints(AffineConstraints<double> &constraints) const;

    /**
     * Per node of a surface, the nodes (indices on that surface) and weights
     * it follows, through its dofs of the given component; empty where it
     * does not hang. Throws if a hanging node follows one not on the surface.
     */
    template <int dim>
    std::vector<std::vector<std::pair<unsigned int, double>>>
    node_parents(const ContactSurface<dim> &surface,
                 const unsigned int         component) const;

    /**
     * Per face of a 3-D surface of degree 2 and per edge, in the order of
     * the face's boundary (0,0)-(1,0)-(1,1)-(0,1): into how many equal
     * parts the finest faces that hang on it divide it (a power of 2; 1
     * where none does). A face's segment polygon then follows its edges
     * with the points of those finer faces: coarse and fine polygons tile.
     */
    std::vector<std::array<unsigned int, 4>>
    edge_subdivisions(const ContactSurface<3> &surface) const;

  private:
    std::map<types::global_dof_index, Followed> followed;
  };

  /** The linear system a contact assembly adds to. */
  struct ContactLinearSystem
  {
    // constrained rows are skipped
    const AffineConstraints<double> &constraints;
    const bool                       with_jacobian;
    TrilinosWrappers::MPI::Vector   &residual;
    TrilinosWrappers::SparseMatrix  &jacobian;
    TrilinosWrappers::MPI::Vector   &residual_full; // all force rows
    const HangingSurfaceDofs        &hanging;

    /**
     * Adds factor times the derivatives, (column, value) pairs, to a row of
     * the Jacobian: columns of hanging degrees of freedom go to the columns
     * they follow, other constrained columns are dropped.
     */
    template <typename Derivatives>
    void
    add_row(const types::global_dof_index row,
            const Derivatives            &derivatives,
            const double                  factor = 1.) const;
  };
} // namespace ContactDynamics

#endif
