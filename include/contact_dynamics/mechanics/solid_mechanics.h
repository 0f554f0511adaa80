// The bulk of the bodies: inertia, Rayleigh damping, internal and body
// forces, their Jacobian, and the energy integrals.
#ifndef contact_dynamics_mechanics_solid_mechanics_h
#define contact_dynamics_mechanics_solid_mechanics_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/mechanics/bodies.h>
#include <contact_dynamics/mechanics/material.h>

#include <memory>
#include <string>
#include <vector>

DEAL_II_NAMESPACE_OPEN
class DynamicSparsityPattern;
DEAL_II_NAMESPACE_CLOSE

namespace ContactDynamics
{
  using namespace dealii;
  using VectorType = TrilinosWrappers::MPI::Vector;
  using MatrixType = TrilinosWrappers::SparseMatrix;

  /**
   * Residual R(u) = M a(u) + C v(u) + f_int(u) - f_body with C = alpha M +
   * beta K0 per body, where a(u) and v(u) follow from the time integrator
   * (d a/d u = c_a, d v/d u = c_v). The displacement is the first dim
   * components of the finite element; further components (contact
   * multipliers) are left to others.
   *
   * M, C and the stiffness K of the linear elastic bodies do not depend on
   * the state: setup() assembles them once, and the residual takes their
   * part from matrix-vector products. Only the cells of nonlinear bodies
   * are visited per Newton iteration (WorkStream; one thread per process
   * unless DEAL_II_THREADS_PER_PROCESS asks for more).
   */
  template <int dim>
  class SolidMechanics
  {
  public:
    /** The cells' geometry is that of `mapping`. */
    SolidMechanics(const Mapping<dim>                &mapping,
                   const DoFHandler<dim>             &dof_handler,
                   const std::vector<BodyParameters> &bodies);

    /**
     * After the degrees of freedom are distributed: the state-independent
     * matrices and the body force. `constraints` are those every Jacobian
     * of assemble() is built with (homogeneous).
     */
    void
    setup(const AffineConstraints<double> &constraints);

    /**
     * The couplings of the bulk (displacements with each other) into
     * `dsp`, without the entries that `constraints` eliminate.
     */
    void
    make_sparsity_pattern(const AffineConstraints<double> &constraints,
                          DynamicSparsityPattern          &dsp) const;

    /** All bodies are linear elastic: the Jacobian is constant. */
    bool
    is_linear() const;

    /**
     * Residual at (u, v, a). With constraints (homogeneous for Newton
     * increments) into `residual` and, if asked, `jacobian`; without them
     * into `residual_full`, whose entries at Dirichlet degrees of freedom are
     * the reaction forces. The Jacobian's constraints are those of setup().
     * Vectors may be ghosted or not; u must be ghosted if a body is
     * nonlinear.
     */
    void
    assemble(const VectorType                &u,
             const VectorType                &v,
             const VectorType                &a,
             const double                     c_a,
             const double                     c_v,
             const AffineConstraints<double> &constraints,
             const bool                       with_jacobian,
             VectorType                      &residual,
             MatrixType                      &jacobian,
             VectorType                      &residual_full) const;

    /**
     * The system M a0 = -(C v0 + f_int(u0) - f_body) for a consistent
     * initial acceleration; `constraints` carry the prescribed
     * accelerations.
     */
    void
    assemble_initial_acceleration_system(
      const VectorType                &u,
      const VectorType                &v,
      const AffineConstraints<double> &constraints,
      MatrixType                      &mass_matrix,
      VectorType                      &rhs) const;

    /** The body force vector (constant in time). */
    const VectorType &
    body_force() const
    {
      return body_force_vector;
    }

    /** 1/2 v.M v */
    double
    kinetic_energy(const VectorType &v) const;

    /** The consistent mass matrix (unconstrained). */
    const MatrixType &
    mass_matrix() const
    {
      return mass;
    }

    /**
     * M a as assemble() puts it into `residual_full` (rows of hanging
     * nodes added to the rows they follow): `force` (not ghosted) receives
     * factor M a.
     */
    void
    inertia_force(const VectorType &a,
                  const double      factor,
                  VectorType       &force) const;

    /** Integral of the stored energy density. */
    double
    elastic_energy(const VectorType &u) const;

    /** v1.C v2 with the Rayleigh damping matrix C. */
    double
    damping_product(const VectorType &v1, const VectorType &v2) const;

    /** The geometry of the cells. */
    const Mapping<dim> &
    get_mapping() const
    {
      return mapping;
    }

    const Material<dim> &
    material(const types::material_id id) const
    {
      return *materials[id];
    }

    /**
     * Corners of neo-Hookean elements where det F <= 0 in the state
     * `u_ghost` (ghosted): "" if none, else what and where (the same on
     * every process). The quadrature points can all be fine while a corner
     * is inverted, and the stresses written there would be NaN.
     */
    std::string
    inverted_corner(const VectorType &u_ghost) const;

    /**
     * The linear elastic body whose largest strain norm (cell centres of
     * the state `u_ghost`, ghosted) exceeds its Small strain limit the
     * most: what, how much and where, or "" (the same on every process).
     */
    std::string
    small_strain_excess(const VectorType &u_ghost) const;

  private:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

    /**
     * factor_m M + factor_c C + factor_k K (K: the linear elastic bodies)
     * into `matrix`, cell by cell through `constraints`; with `rhs`, the
     * inhomogeneities of the constraints go there.
     */
    void
    assemble_constant_matrix(const double                     factor_m,
                             const double                     factor_c,
                             const double                     factor_k,
                             const AffineConstraints<double> &constraints,
                             MatrixType                      &matrix,
                             VectorType *rhs = nullptr) const;

    /**
     * The nonlinear bodies' internal forces into `force` and, if given,
     * their tangent into `tangent`; returns their stored energy.
     */
    double
    assemble_nonlinear(const VectorType                &u,
                       const AffineConstraints<double> &constraints,
                       VectorType                      *force,
                       MatrixType                      *tangent) const;

    /**
     * Finds where the entries of the nonlinear cells' displacement blocks
     * and of constant_jacobian sit in the value array of `jacobian`, whose
     * sparsity pattern was made last. A cell with a constrained or
     * non-owned dof keeps the general path through the constraints.
     */
    void
    find_positions(const MatrixType &jacobian) const;

    /** Whether the positions were found for this matrix's storage. */
    bool
    positions_fit(const MatrixType &jacobian) const;

    /**
     * Adds the rows of the hanging nodes of `full` to the rows they follow
     * and drops them (C^T r); `copy` is scratch.
     */
    void
    move_hanging_rows(VectorType &full, VectorType &copy) const;

    /** x itself, or a copy without ghosts for matrix-vector products. */
    const VectorType &
    owned(const VectorType &x, VectorType &scratch) const;

    const Mapping<dim>                         &mapping;
    const DoFHandler<dim>                      &dof_handler;
    const std::vector<BodyParameters>          &bodies;
    std::vector<std::unique_ptr<Material<dim>>> materials;

    const AffineConstraints<double> *jacobian_constraints = nullptr;
    // the owned rows of hanging nodes (adapted meshes), which the residual
    // adds to the rows they follow; whether any process has one
    std::vector<
      std::pair<types::global_dof_index,
                std::vector<std::pair<types::global_dof_index, double>>>>
                              hanging_rows;
    bool                      any_hanging_rows = false;
    std::vector<CellIterator> owned_cells, nonlinear_cells;
    // their shape gradients and JxW at the quadrature points, cell by cell
    std::vector<Tensor<1, dim>> nonlinear_gradients;
    std::vector<double>         nonlinear_JxW;
    VectorType                  body_force_vector;
    // unconstrained, for residuals and energies: mass, damping, stiffness
    // of the linear elastic bodies
    MatrixType mass, damping, linear_stiffness;
    bool       has_linear_cells = false;
    // c_a M + c_v C + K through the constraints of the Jacobian, for the
    // last (c_a, c_v): the time step changes rarely
    mutable MatrixType constant_jacobian;
    mutable double     constant_jacobian_c_a = -1, constant_jacobian_c_v = -1;
    mutable VectorType scratch[3];
    // the Jacobian's value array at these positions takes the entries
    // directly instead of searching each one (per sparsity pattern; empty
    // when the matrix's storage is not contiguous)
    mutable bool positions_found = false;
    // the matrix they were found for (a safeguard besides the reset in
    // make_sparsity_pattern): its Epetra object, values and their number
    mutable const void               *positions_matrix   = nullptr;
    mutable const double             *positions_values   = nullptr;
    mutable int                       positions_nonzeros = -1;
    mutable std::vector<unsigned int> cell_positions;
    // per nonlinear cell: its first entry in cell_positions, or none
    mutable std::vector<std::size_t>  first_position;
    mutable std::vector<unsigned int> position_dofs; // the cell's u dofs
    mutable std::vector<unsigned int> constant_positions;
  };
} // namespace ContactDynamics

#endif
