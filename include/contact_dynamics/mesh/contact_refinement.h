// Adaptive refinement that follows the contact: which cells to refine and
// coarsen, given the points where contact is or is about to be. The
// simulator transfers its state to the new mesh (doc/refinement.md).
#ifndef contact_dynamics_mesh_contact_refinement_h
#define contact_dynamics_mesh_contact_refinement_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <contact_dynamics/solvers/trilinos_forward.h>

#include <vector>

DEAL_II_NAMESPACE_OPEN
template <int dim, int spacedim>
class DoFHandler;
template <int dim, int spacedim>
class Triangulation;
template <typename number>
class AffineConstraints;
class IndexSet;
DEAL_II_NAMESPACE_CLOSE

namespace ContactDynamics
{
  using namespace dealii;
  using VectorType = TrilinosWrappers::MPI::Vector;

  /** The `Mesh refinement` subsection. */
  struct RefinementParameters
  {
    bool         adapt_to_contact  = false;
    unsigned int interval          = 1;
    bool         on_contact_change = true;
    unsigned int maximum_levels    = 2;
    unsigned int maximum_cells     = 1000000;
    double       buffer_cells      = 2;
    double       lookahead_steps   = 2;
    unsigned int passes_per_step   = 1;
    bool         coarsen           = true;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /**
   * Sets refine and coarsen flags on the locally owned active cells of the
   * distributed mesh of `dof_handler`: a cell whose current position (the
   * displacement `u`, ghosted) comes within `buffer_cells` units of a
   * contact point is refined, up to `base_level + maximum_levels`; one
   * farther than (buffer_cells + 1) units of its parent is coarsened, down
   * to `base_level`. The unit of a cell is the diameter the cells touching
   * the contact zone have at its level (the largest of them), or its own
   * diameter if that is smaller, so that large far cells of a graded mesh
   * are not refined by their own size. Refinements that would make
   * more than `maximum_cells` cells are dropped, the farthest first.
   * Returns the number of refinements dropped (collective).
   */
  template <int dim>
  unsigned int
  mark_cells_near_contact(const DoFHandler<dim, dim>    &dof_handler,
                          const VectorType              &u,
                          const std::vector<Point<dim>> &contact_points,
                          const RefinementParameters    &parameters,
                          const unsigned int             base_level);

  /**
   * Before the flagged cells are coarsened: replaces `v` (owned) by its
   * projection, in the norm of the `mass` matrix, onto the functions of
   * the present mesh that the coarsened families represent exactly (their
   * removed vertices interpolated from the parents' vertices), keeping the
   * values of the `fixed` degrees of freedom and the `hanging` constraints
   * of the present mesh. Constant and linear fields are in that space: on
   * a free body the momentum and the angular momentum do not change, and
   * with no fixed values (or fixed values of zero) the kinetic energy
   * cannot grow; the interpolation to the coarser mesh is then exact. Returns
   * false (v unchanged) if no family is coarsened. Collective.
   */
  template <int dim>
  bool
  project_before_coarsening(const DoFHandler<dim, dim>           &dof_handler,
                            const TrilinosWrappers::SparseMatrix &mass,
                            const AffineConstraints<double>      &hanging,
                            const IndexSet                       &fixed,
                            VectorType                           &v);

  /**
   * y <- C^T y for homogeneous constraints C: the rows of constrained
   * degrees of freedom with entries go to the rows they follow, then every
   * constrained row is zero (collective).
   */
  void
  condense_rows(const AffineConstraints<double> &constraints, VectorType &y);

  /**
   * Solves C^T M C x = b for the condensed right-hand side b (given in x)
   * by preconditioned CG to 1e-14, and distributes x (homogeneous
   * constraints). Collective.
   */
  void
  solve_constrained_mass_system(const TrilinosWrappers::SparseMatrix &mass,
                                const AffineConstraints<double> &constraints,
                                VectorType                      &x);

  /** Whether any process has a flagged cell (collective). */
  template <int dim>
  bool
  any_cell_flagged(const Triangulation<dim, dim> &triangulation,
                   const MPI_Comm                 comm);
} // namespace ContactDynamics

#endif
