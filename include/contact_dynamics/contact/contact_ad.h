// Forward-mode automatic differentiation (Sacado) for contact patches. Only
// formulation sources include this header: Sacado is heavy.
#ifndef contact_dynamics_contact_contact_ad_h
#define contact_dynamics_contact_contact_ad_h

#include <deal.II/differentiation/ad/sacado_math.h>
#include <deal.II/differentiation/ad/sacado_number_types.h>
#include <deal.II/differentiation/ad/sacado_product_types.h>

#include <contact_dynamics/contact/segment_geometry.h>
#include <contact_dynamics/contact/surface_contact.h>

#include <utility>
#include <vector>

namespace ContactDynamics
{
  namespace ContactAD
  {
    using AD = Sacado::Fad::DFad<double>;
    using SegmentGeometry::Vec;

    /** The value only: drops derivatives (approximate Jacobians). */
    inline AD
    constant(const AD &x)
    {
      return AD(x.val());
    }

    inline Vec<AD>
    constant(const Vec<AD> &x)
    {
      Vec<AD> c;
      for (unsigned int d = 0; d < 2; ++d)
        c[d] = constant(x[d]);
      return c;
    }

    inline Vec<double>
    value(const Vec<AD> &x)
    {
      return Vec<double>({x[0].val(), x[1].val()});
    }

    /** Independent variable k of n with the given value. */
    inline AD
    variable(const unsigned int n, const unsigned int k, const double x)
    {
      return AD(n, k, x);
    }

    /** Adds x (value and derivatives) to a linearized nodal quantity. */
    inline void
    add_to(LinearizedValue                            &target,
           const AD                                   &x,
           const std::vector<types::global_dof_index> &unknowns)
    {
      target.value += x.val();
      for (unsigned int k = 0; k < unknowns.size() && k < unsigned(x.size());
           ++k)
        if (x.dx(k) != 0)
          target.derivatives[unknowns[k]] += x.dx(k);
    }

    /** The nonzero derivatives of x with respect to the global unknowns. */
    inline std::vector<std::pair<types::global_dof_index, double>>
    derivatives(const AD                                   &x,
                const std::vector<types::global_dof_index> &unknowns)
    {
      std::vector<std::pair<types::global_dof_index, double>> result;
      for (unsigned int k = 0; k < unknowns.size() && k < unsigned(x.size());
           ++k)
        if (x.dx(k) != 0)
          result.emplace_back(unknowns[k], x.dx(k));
      return result;
    }

    /**
     * Positions (and Newmark velocities) of surface nodes as AD numbers:
     * each call registers the node's displacement unknowns as the next
     * independent variables, in the order of `unknowns`.
     */
    template <int dim>
    class NodeVariables
    {
    public:
      NodeVariables(const std::vector<types::global_dof_index> &unknowns,
                    const TrialState                           &state)
        : unknowns(unknowns)
        , state(state)
      {}

      void
      add(const ContactSurface<dim> &surface,
          const unsigned int         node,
          Vec<AD>                   &x,
          Vec<AD>                   &v)
      {
        for (unsigned int d = 0; d < 2; ++d, ++next)
          {
            Assert(unknowns[next] == surface.dofs[node][d], ExcInternalError());
            x[d] = AD(unknowns.size(),
                      next,
                      surface.reference[node][d] + state.u(unknowns[next]));
            // v = c_v u + (terms of the old state)
            v[d]       = state.c_v * x[d];
            v[d].val() = state.v(unknowns[next]);
          }
      }

      /** The next independent variable: a multiplier. */
      AD
      multiplier()
      {
        const unsigned int k = next++;
        return AD(unknowns.size(), k, state.u(unknowns[k]));
      }

    private:
      const std::vector<types::global_dof_index> &unknowns;
      const TrialState                           &state;
      unsigned int                                next = 0;
    };
  } // namespace ContactAD
} // namespace ContactDynamics

#endif
