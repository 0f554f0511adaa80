// The bulk of the bodies: inertia, Rayleigh damping, internal and body
// forces, their Jacobian, and the energy integrals.
#ifndef contact_dynamics_mechanics_solid_mechanics_h
#define contact_dynamics_mechanics_solid_mechanics_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/mechanics/bodies.h>
#include <contact_dynamics/mechanics/material.h>

#include <memory>
#include <vector>

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
   */
  template <int dim>
  class SolidMechanics
  {
  public:
    SolidMechanics(const DoFHandler<dim>             &dof_handler,
                   const std::vector<BodyParameters> &bodies);

    /** All bodies are linear elastic: the Jacobian is constant. */
    bool
    is_linear() const;

    /**
     * Residual at (u, v, a). With constraints (homogeneous for Newton
     * increments) into `residual` and, if asked, `jacobian`; without them
     * into `residual_full`, whose entries at Dirichlet degrees of freedom are
     * the reaction forces.
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
    void
    assemble_body_force(VectorType &f) const;

    /** 1/2 v.M v */
    double
    kinetic_energy(const VectorType &v) const;

    /** Integral of the stored energy density. */
    double
    elastic_energy(const VectorType &u) const;

    /** v1.C v2 with the Rayleigh damping matrix C. */
    double
    damping_product(const VectorType &v1, const VectorType &v2) const;

    const Material<dim> &
    material(const types::material_id id) const
    {
      return *materials[id];
    }

  private:
    const DoFHandler<dim>                      &dof_handler;
    const std::vector<BodyParameters>          &bodies;
    std::vector<std::unique_ptr<Material<dim>>> materials;
  };
} // namespace ContactDynamics

#endif
