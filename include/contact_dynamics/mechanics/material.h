// Constitutive models: the first Piola-Kirchhoff stress, its derivative with
// respect to the deformation gradient and the stored energy density, all as
// functions of the displacement gradient.
#ifndef contact_dynamics_mechanics_material_h
#define contact_dynamics_mechanics_material_h

#include <deal.II/base/tensor.h>

#include <memory>
#include <string>

DEAL_II_NAMESPACE_OPEN
class ParameterHandler;
DEAL_II_NAMESPACE_CLOSE

namespace ContactDynamics
{
  using namespace dealii;

  /** Parameters of one body's material, read from `subsection Body <name>`. */
  struct MaterialParameters
  {
    enum class Model
    {
      linear_elastic,
      neo_hookean
    };

    // the defaults of the parameter file
    Model  model                          = Model::linear_elastic;
    double youngs_modulus                 = 1e6;
    double poissons_ratio                 = 0.3;
    double density                        = 1.;
    double rayleigh_mass_coefficient      = 0.;
    double rayleigh_stiffness_coefficient = 0.;
    // linear elastic bodies: the strain norm above which a warning says the
    // model no longer applies (0: no check)
    double small_strain_limit = 0.2;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** The model of a `Material model` entry ("linear elastic", ...). */
    static Model
    model_named(const std::string &name);

    double
    lame_lambda() const;
    double
    shear_modulus() const;
  };

  /**
   * A hyperelastic material in plane strain (dim = 2) or 3-D. Small-strain
   * models ignore the difference between reference and current
   * configuration: their "first Piola stress" is the Cauchy stress of the
   * linearized strain.
   */
  template <int dim>
  class Material
  {
  public:
    virtual ~Material() = default;

    /** Whether the residual is linear in the displacement. */
    virtual bool
    is_linear() const = 0;

    /**
     * Stress P(grad u), tangent dP/dF and energy density W(grad u). Throws
     * ExcMessage if the deformation is inadmissible (det F <= 0).
     */
    virtual void
    evaluate(const Tensor<2, dim> &grad_u,
             Tensor<2, dim>       &stress,
             Tensor<4, dim>       &tangent,
             double               &energy_density) const = 0;

    /** Full 3-D Cauchy stress (out-of-plane component in plane strain). */
    virtual Tensor<2, 3>
    cauchy_stress(const Tensor<2, dim> &grad_u) const = 0;

    /**
     * The small-strain elasticity tensor of the unloaded material, used for
     * stiffness-proportional Rayleigh damping (a constant damping matrix
     * that dissipates for every velocity field).
     */
    const Tensor<4, dim> &
    reference_elasticity() const;

    const MaterialParameters &
    parameters() const;

  protected:
    explicit Material(const MaterialParameters &parameters);

    MaterialParameters parameters_;
    Tensor<4, dim>     elasticity_;
  };

  template <int dim>
  std::unique_ptr<Material<dim>>
  create_material(const MaterialParameters &parameters);

  /** Von Mises equivalent stress of a 3-D stress tensor. */
  double
  von_mises_stress(const Tensor<2, 3> &stress);
} // namespace ContactDynamics

#endif
