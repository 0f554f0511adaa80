// Algebraic multigrid for the condensed contact system in each secondary
// node's frame (issue 40, item 2): the condensed system A x = b becomes
// (L A T) y = L b, x = T y, with T rotating each condensed node's
// displacements into the frame of its multiplier block B = Q R (normal,
// then tangents) and L bringing the node's equations back into that order,
// scaled to the rotated stiffness' diagonal. ML builds its hierarchy on a
// copy whose constrained frame components (active normal, stick) are
// removed from rows and columns, with rigid-body modes rotated alike; a
// cycle is followed by the constraint rows, solved for their component
// given the others (a block lower-triangular preconditioner). GMRES
// solves the transformed system itself, so the Newton iterates are those of
// the condensed system.
#ifndef contact_dynamics_solvers_contact_frame_multigrid_h
#define contact_dynamics_solvers_contact_frame_multigrid_h

#include <deal.II/base/types.h>

#include <contact_dynamics/solvers/trilinos_forward.h>

#include <memory>
#include <string>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  /**
   * ML's smoother on every level: its name ("Chebyshev", "symmetric
   * Gauss-Seidel") and sweeps (the polynomial degree for Chebyshev).
   */
  struct AmgSmoother
  {
    std::string  type   = "Chebyshev";
    unsigned int sweeps = 2;
  };

  /**
   * A condensed secondary node in its frame (MultiplierCondensation).
   */
  struct NodeFrame
  {
    // the node's displacement dofs (owned)
    std::vector<types::global_dof_index> dofs;
    // axes[b][d]: component d of the orthonormal frame axis b
    std::vector<std::vector<double>> axes;
    // frame equation b = sum_d to_frame[b][d] * (condensed row of dofs[d])
    std::vector<std::vector<double>> to_frame;
    // axis b carries a constraint (active normal, stick)
    std::vector<bool> constrained;
  };

  /**
   * The frame of a condensed node with displacement dofs `dofs`: q[d][b]
   * is component d of axis b (B = Q R), stiffness[d][e] the Jacobian's
   * entry in row dofs[d] and column dofs[e], coefficients[b][e] that of
   * the node's equation b (axis order) at dofs[e]; equation placed[d] sits
   * on row dofs[d] multiplied by factors[d]; `constrained` per equation.
   * Each equation is scaled so that its coefficient on its own axis is
   * the rotated stiffness |q_b^T K q_b|.
   */
  NodeFrame
  make_node_frame(const std::vector<types::global_dof_index> &dofs,
                  const std::vector<std::vector<double>>     &q,
                  const std::vector<std::vector<double>>     &stiffness,
                  const std::vector<std::vector<double>>     &coefficients,
                  const std::vector<unsigned int>            &placed,
                  const std::vector<double>                  &factors,
                  const std::vector<bool>                    &constrained);

  class ContactFrameMultigrid
  {
  public:
    ContactFrameMultigrid();
    ~ContactFrameMultigrid();

    /**
     * The transformed matrix L A T and right-hand side L b for the frames
     * of the condensation that produced `matrix`. Collective.
     */
    void
    transform(const TrilinosWrappers::SparseMatrix &matrix,
              const TrilinosWrappers::MPI::Vector  &rhs,
              const std::vector<NodeFrame>         &frames);

    const TrilinosWrappers::SparseMatrix &
    matrix() const;

    const TrilinosWrappers::MPI::Vector &
    rhs() const;

    /** x = T y. */
    void
    back_transform(const TrilinosWrappers::MPI::Vector &y,
                   TrilinosWrappers::MPI::Vector       &x) const;

    /**
     * Whether the constrained components differ from those of the
     * hierarchy (or there is none). Collective.
     */
    bool
    needs_build() const;

    /**
     * ML on the transformed matrix with the constrained components
     * removed; `null_space`: n_modes vectors over the locally owned dofs,
     * one after the other, rotated here.
     */
    void
    build(const std::vector<double> &null_space,
          const unsigned int         n_modes,
          const unsigned int         dofs_per_vertex,
          const AmgSmoother         &smoother);

    /** One cycle, then the constraint rows (the preconditioner). */
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

  private:
    std::unique_ptr<TrilinosWrappers::SparseMatrix> rotation, transformed;
    // L A T's nonzero entries (in-place transform)
    std::unique_ptr<TrilinosWrappers::SparseMatrix>    compact;
    std::unique_ptr<TrilinosWrappers::MPI::Vector>     transformed_rhs;
    // (in this order: the hierarchy goes before its matrix)
    std::unique_ptr<TrilinosWrappers::SparseMatrix>    amg_matrix;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
    // dst of a cycle with the constraint rows' columns as ghosts
    std::unique_ptr<TrilinosWrappers::MPI::Vector> ghosted;
    // the owned constrained components, sorted, of the last transform()
    // and of the hierarchy
    std::vector<types::global_dof_index> constrained, built_constrained;
    // their local indices and the transformed matrix's diagonal there
    std::vector<unsigned int> constrained_local;
    std::vector<double>       constrained_diagonal;
    // the constraint rows (CSR; columns local to `ghosted`)
    std::vector<unsigned int>   row_start;
    std::vector<int>            row_columns;
    std::vector<double>         row_values;
    bool                        any_constrained = false;
    mutable std::vector<double> corrections;
    // frames of the last transform(), for the rotation of the modes
    std::vector<NodeFrame> frames;
    // dst = M src on the frames' dofs, M(dofs[i], dofs[j]) = block(f, i, j)
    // (src and dst differ; dst keeps its other entries)
    template <typename Block>
    void
    apply_blocks(TrilinosWrappers::MPI::Vector       &dst,
                 const TrilinosWrappers::MPI::Vector &src,
                 const Block                         &block) const;

    void
    store_constraint_rows();

    // whether L A T was formed in the matrix's own pattern (T not stored)
    bool in_place = false;
  };

  /**
   * ML smoothed aggregation on `matrix` with the smoother `smoother`, with
   * `n_modes` near-null-space vectors over the locally owned dofs (one
   * after the other) if there are.
   */
  void
  initialize_amg(TrilinosWrappers::PreconditionAMG    &amg,
                 const TrilinosWrappers::SparseMatrix &matrix,
                 const std::vector<double>            &null_space,
                 const unsigned int                    n_modes,
                 const unsigned int                    dofs_per_vertex,
                 const AmgSmoother                    &smoother);
} // namespace ContactDynamics

#endif
