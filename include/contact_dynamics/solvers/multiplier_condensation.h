// Static condensation of the contact multipliers from a Newton system, node
// by node (Popp, Gitterle, Gee and Wall 2010): exact where the multipliers
// of a secondary node act only on that node's own displacement rows
// (node-to-segment); for this code's mortar force, whose derivative couples
// neighbours by terms of the size of the gap, an approximation of the
// Jacobian (doc/solvers.md).
#ifndef contact_dynamics_solvers_multiplier_condensation_h
#define contact_dynamics_solvers_multiplier_condensation_h

#include <deal.II/base/types.h>

#include <contact_dynamics/solvers/contact_frame_multigrid.h>
#include <contact_dynamics/solvers/trilinos_forward.h>

#include <memory>
#include <vector>


namespace ContactDynamics
{
  using namespace dealii;

  namespace internal
  {
    /** dlambda_m = -e - F du of one condensed multiplier
     * (multiplier_substitution.h). */
    struct MultiplierElimination;
  } // namespace internal

  /**
   * The unknowns of one secondary node owned by this process: its
   * displacement dofs and the multipliers (normal, tangential) that are
   * unknowns of the Newton system (not constrained).
   */
  struct MultiplierGroup
  {
    std::vector<types::global_dof_index> displacements;
    std::vector<types::global_dof_index> multipliers;
  };

  /**
   * For a Newton system J dx = -r, with the unknowns x = (u, lambda):
   * per group g the rows of its displacements, J_s u du + B dlambda_g =
   * -r_s with the dim x k block B = J[s, lambda_g], give dlambda_g =
   * E (-r_s - J_s du), E = R^-1 Q_1^T from B = Q_1 R. Every other row gets
   * its multiplier columns replaced by this; the rows of the group's
   * displacements are replaced by the k condensed multiplier rows and by
   * the dim - k rotated displacement rows Q_2^T (J_s du + r_s) = 0, placed
   * on the displacement rows so that their diagonals are large (an
   * iterative solver and its preconditioner see a displacement-only,
   * elasticity-like matrix); the multiplier rows become identity rows.
   * A group whose block B is rank deficient (a secondary node held by
   * Dirichlet conditions) stays uncondensed.
   */
  class MultiplierCondensation
  {
  public:
    MultiplierCondensation();
    ~MultiplierCondensation();

    /**
     * Builds the condensed matrix and right-hand side from `jacobian` and
     * `rhs` (J dx = -rhs). With `copy_jacobian`, the matrix is a copy of
     * the Jacobian with the changed rows rewritten if its pattern holds the
     * fill-in (fast; structural zeros at the multipliers); otherwise a
     * matrix with its own pattern. Collective.
     */
    void
    condense(const TrilinosWrappers::SparseMatrix &jacobian,
             const TrilinosWrappers::MPI::Vector  &rhs,
             const std::vector<MultiplierGroup>   &groups,
             const bool                            copy_jacobian);

    /**
     * Adds to a (structurally symmetric) sparsity pattern the entries the
     * condensation fills in: a row that couples to a multiplier of group g
     * gets the columns of g's displacement rows. With them the condensed
     * matrix is a copy of the Jacobian with the affected rows rewritten;
     * without, condense() builds it anew (slower).
     */
    static void
    add_fill_in(DynamicSparsityPattern             &dsp,
                const std::vector<MultiplierGroup> &groups);

    /** Rows and the columns the condensation fills into each of them. */
    struct FillIn
    {
      std::vector<types::global_dof_index> rows, columns;
    };

    /**
     * The fill-in of add_fill_in() as a list, read from `pattern`, whose
     * rows of the groups' displacements and multipliers must be complete
     * (with several processes: the pattern after it was distributed to
     * the owners of its rows). The rows it fills may be owned elsewhere.
     */
    static std::vector<FillIn>
    fill_in(const DynamicSparsityPattern       &pattern,
            const std::vector<MultiplierGroup> &groups);

    const TrilinosWrappers::SparseMatrix &
    matrix() const;

    const TrilinosWrappers::MPI::Vector &
    rhs() const;

    /**
     * `solution` holds the displacement increments of the condensed
     * system (zeros at the condensed multipliers): sets the multiplier
     * increments. Collective.
     */
    void
    recover(TrilinosWrappers::MPI::Vector &solution) const;

    /**
     * The condensed nodes of this process after the last condense(), each
     * in the frame of its multiplier block B = Q R: the axes (columns of
     * Q), its equations in that order scaled to the diagonal of the
     * rotated stiffness, and which axes carry a constraint (an active
     * normal or a sticking tangential condition: the multiplier's row has
     * no multiplier entries).
     */
    const std::vector<NodeFrame> &
    node_frames() const
    {
      return frames;
    }

    /** Multipliers eliminated in the last condense() (all processes). */
    unsigned int
    n_condensed() const
    {
      return n_condensed_multipliers;
    }

  private:
    std::unique_ptr<TrilinosWrappers::SparseMatrix> condensed_matrix;
    std::unique_ptr<TrilinosWrappers::MPI::Vector>  condensed_rhs;
    // dlambda_m = -e_m - F_m du for the owned condensed multipliers
    std::vector<internal::MultiplierElimination> eliminations;
    unsigned int                                 n_condensed_multipliers = 0;
    std::vector<NodeFrame>                       frames;
  };
} // namespace ContactDynamics

#endif
