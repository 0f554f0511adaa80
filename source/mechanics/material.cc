#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <contact_dynamics/mechanics/material.h>
#include <contact_dynamics/parameters.h>

#include <cmath>

namespace ContactDynamics
{
  namespace
  {
    const Selection<MaterialParameters::Model> model_names{
      {MaterialParameters::Model::linear_elastic, "linear elastic"},
      {MaterialParameters::Model::neo_hookean, "neo-Hookean"}};
  } // namespace

  void
  MaterialParameters::declare_parameters(ParameterHandler &prm)
  {
    const MaterialParameters defaults;
    prm.declare_entry("Material model",
                      model_names.name(defaults.model),
                      model_names.pattern(),
                      "Constitutive model. 'linear elastic': small strain, "
                      "the residual is linear in the displacement (cheapest). "
                      "'neo-Hookean': compressible neo-Hookean, finite strain, "
                      "total Lagrangian, W = mu/2 (tr C - 3) - mu ln J + "
                      "lambda/2 (ln J)^2.");
    prm.declare_entry("Young's modulus",
                      default_text(defaults.youngs_modulus),
                      Patterns::Double(1e-300),
                      "Young's modulus E (> 0), in stress units.");
    prm.declare_entry("Poisson's ratio",
                      default_text(defaults.poissons_ratio),
                      Patterns::Double(-0.999, 0.4999),
                      "Poisson's ratio nu, in [-0.999, 0.4999].");
    prm.declare_entry("Density",
                      default_text(defaults.density),
                      Patterns::Double(1e-300),
                      "Mass density rho (> 0), mass per unit volume.");
    prm.declare_entry("Rayleigh mass coefficient",
                      default_text(defaults.rayleigh_mass_coefficient),
                      Patterns::Double(0),
                      "alpha in the damping matrix C = alpha M + beta K0 "
                      "(1/time, >= 0).");
    prm.declare_entry(
      "Rayleigh stiffness coefficient",
      default_text(defaults.rayleigh_stiffness_coefficient),
      Patterns::Double(0),
      "beta in C = alpha M + beta K0 (time, >= 0); K0 is the small-strain "
      "stiffness of the unloaded body, so C is constant and dissipative for "
      "both material models. The paper's '10 % stiffness damping' is 0.1.");
    prm.declare_entry(
      "Small strain limit",
      default_text(defaults.small_strain_limit),
      Patterns::Double(0),
      "Linear elastic bodies only: once the norm of the small-strain "
      "tensor (the symmetric displacement gradient, at a cell centre) "
      "exceeds this value after a step, a warning names the body, the "
      "strain, the step and the place, once per run: beyond small strains "
      "and rotations linear elasticity is wrong (a rotation by 31 degrees "
      "alone gives a strain norm of 0.2, and stresses where there are none) and the "
      "energy balance is meaningless; use Material model = neo-Hookean. 0: "
      "no check. The default 0.2 passes the shipped linear examples (the bar "
      "impact reaches 0.1); costs one gradient per cell and step.");
  }

  void
  MaterialParameters::parse_parameters(ParameterHandler &prm)
  {
    model                     = model_named(prm.get("Material model"));
    small_strain_limit        = prm.get_double("Small strain limit");
    youngs_modulus            = prm.get_double("Young's modulus");
    poissons_ratio            = prm.get_double("Poisson's ratio");
    density                   = prm.get_double("Density");
    rayleigh_mass_coefficient = prm.get_double("Rayleigh mass coefficient");
    rayleigh_stiffness_coefficient =
      prm.get_double("Rayleigh stiffness coefficient");
  }

  MaterialParameters::Model
  MaterialParameters::model_named(const std::string &name)
  {
    return model_names.value(name);
  }

  double
  MaterialParameters::lame_lambda() const
  {
    return youngs_modulus * poissons_ratio /
           ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
  }

  double
  MaterialParameters::shear_modulus() const
  {
    return youngs_modulus / (2. * (1. + poissons_ratio));
  }



  template <int dim>
  Material<dim>::Material(const MaterialParameters &parameters)
    : parameters_(parameters)
  {
    const double lambda = parameters.lame_lambda();
    const double mu     = parameters.shear_modulus();
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            elasticity_[i][j][k][l] =
              lambda * (i == j) * (k == l) +
              mu * ((i == k) * (j == l) + (i == l) * (j == k));
  }

  template <int dim>
  const Tensor<4, dim> &
  Material<dim>::reference_elasticity() const
  {
    return elasticity_;
  }

  template <int dim>
  const MaterialParameters &
  Material<dim>::parameters() const
  {
    return parameters_;
  }



  namespace
  {
    template <int dim>
    class LinearElastic : public Material<dim>
    {
    public:
      explicit LinearElastic(const MaterialParameters &p)
        : Material<dim>(p)
      {}

      bool
      is_linear() const override
      {
        return true;
      }

      void
      evaluate(const Tensor<2, dim> &grad_u,
               Tensor<2, dim>       &stress,
               Tensor<4, dim>       &tangent,
               double               &energy_density) const override
      {
        const Tensor<2, dim> strain = 0.5 * (grad_u + transpose(grad_u));
        stress         = double_contract<2, 0, 3, 1>(this->elasticity_, strain);
        tangent        = this->elasticity_;
        energy_density = 0.5 * scalar_product(stress, strain);
      }

      Tensor<2, 3>
      cauchy_stress(const Tensor<2, dim> &grad_u) const override
      {
        const Tensor<2, dim> strain = 0.5 * (grad_u + transpose(grad_u));
        const double         lambda = this->parameters_.lame_lambda();
        const double         mu     = this->parameters_.shear_modulus();
        const double         tr     = trace(strain);
        Tensor<2, 3>         sigma;
        for (unsigned int i = 0; i < 3; ++i)
          sigma[i][i] = lambda * tr;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            sigma[i][j] += 2. * mu * strain[i][j];
        return sigma;
      }
    };



    template <int dim>
    class NeoHookean : public Material<dim>
    {
    public:
      explicit NeoHookean(const MaterialParameters &p)
        : Material<dim>(p)
      {}

      bool
      is_linear() const override
      {
        return false;
      }

      void
      evaluate(const Tensor<2, dim> &grad_u,
               Tensor<2, dim>       &stress,
               Tensor<4, dim>       &tangent,
               double               &energy_density) const override
      {
        const Tensor<2, dim> F =
          Tensor<2, dim>(unit_symmetric_tensor<dim>()) + grad_u;
        const double J = determinant(F);
        AssertThrow(J > 0 && std::isfinite(J),
                    ExcMessage(
                      "Inverted element: det F = " + format_number(J) +
                      " <= 0 in a neo-Hookean body, displacement gradient "
                      "of norm " +
                      format_number(grad_u.norm()) +
                      " (at t = 0: the body's Initial displacement; in a "
                      "step: a step too large for the load or the contact)"));
        const double         lambda = this->parameters_.lame_lambda();
        const double         mu     = this->parameters_.shear_modulus();
        const double         lnJ    = std::log(J);
        const Tensor<2, dim> F_inv  = invert(F);
        const Tensor<2, dim> F_invT = transpose(F_inv);

        stress = mu * (F - F_invT) + lambda * lnJ * F_invT;
        // dP_ij/dF_kl = mu d_ik d_jl + lambda Finv_ji Finv_lk
        //               + (mu - lambda ln J) Finv_jk Finv_li
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int l = 0; l < dim; ++l)
                tangent[i][j][k][l] =
                  mu * (i == k) * (j == l) +
                  lambda * F_inv[j][i] * F_inv[l][k] +
                  (mu - lambda * lnJ) * F_inv[j][k] * F_inv[l][i];
        // tr C - 3 in 3-D equals tr C - dim here (F_zz = 1 in plane strain)
        energy_density = 0.5 * mu * (scalar_product(F, F) - dim) - mu * lnJ +
                         0.5 * lambda * lnJ * lnJ;
      }

      Tensor<2, 3>
      cauchy_stress(const Tensor<2, dim> &grad_u) const override
      {
        const Tensor<2, dim> F =
          Tensor<2, dim>(unit_symmetric_tensor<dim>()) + grad_u;
        const double J = determinant(F);
        Tensor<2, 3> sigma;
        if (!(J > 0))
          {
            for (unsigned int i = 0; i < 3; ++i)
              sigma[i][i] = std::numeric_limits<double>::quiet_NaN();
            return sigma;
          }
        const double lambda = this->parameters_.lame_lambda();
        const double mu     = this->parameters_.shear_modulus();
        // sigma = (mu (b - I) + lambda ln J I) / J, b = F F^T
        const Tensor<2, dim> b = F * transpose(F);
        for (unsigned int i = 0; i < 3; ++i)
          sigma[i][i] = lambda * std::log(J) / J;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            sigma[i][j] += mu * (b[i][j] - (i == j)) / J;
        return sigma;
      }
    };
  } // namespace



  template <int dim>
  std::unique_ptr<Material<dim>>
  create_material(const MaterialParameters &parameters)
  {
    if (parameters.model == MaterialParameters::Model::linear_elastic)
      return std::make_unique<LinearElastic<dim>>(parameters);
    return std::make_unique<NeoHookean<dim>>(parameters);
  }

  double
  von_mises_stress(const Tensor<2, 3> &s)
  {
    const Tensor<2, 3> dev =
      s - trace(s) / 3. * Tensor<2, 3>(unit_symmetric_tensor<3>());
    return std::sqrt(1.5 * scalar_product(dev, dev));
  }

  template class Material<2>;
  template class Material<3>;
  template std::unique_ptr<Material<2>>
  create_material<2>(const MaterialParameters &);
  template std::unique_ptr<Material<3>>
  create_material<3>(const MaterialParameters &);
} // namespace ContactDynamics
