// Forward-mode automatic differentiation (Sacado) for contact patches. Only
// formulation sources include this header: Sacado is heavy.
#ifndef contact_dynamics_contact_contact_ad_h
#define contact_dynamics_contact_contact_ad_h

#include <deal.II/differentiation/ad/sacado_math.h>
#include <deal.II/differentiation/ad/sacado_number_types.h>
#include <deal.II/differentiation/ad/sacado_product_types.h>

#include <contact_dynamics/contact/segment_geometry.h>
#include <contact_dynamics/contact/surface_contact.h>

#include <Sacado_Fad_SFad.hpp>
#include <Sacado_Fad_SLFad.hpp>
#include <type_traits>
#include <utility>
#include <vector>

DEAL_II_NAMESPACE_OPEN
// deal.II's tensors know DFad only: the same for the static storage
namespace internal
{
  template <typename T, int N>
  struct ProductTypeImpl<Sacado::Fad::SFad<T, N>, double>
  {
    using type = Sacado::Fad::SFad<T, N>;
  };

  template <typename T, int N>
  struct ProductTypeImpl<double, Sacado::Fad::SFad<T, N>>
  {
    using type = Sacado::Fad::SFad<T, N>;
  };

  template <typename T, typename U, int N>
  struct ProductTypeImpl<Sacado::Fad::SFad<T, N>, Sacado::Fad::SFad<U, N>>
  {
    using type = Sacado::Fad::SFad<typename ProductType<T, U>::type, N>;
  };

  template <typename T, int N>
  struct ProductTypeImpl<Sacado::Fad::SLFad<T, N>, double>
  {
    using type = Sacado::Fad::SLFad<T, N>;
  };

  template <typename T, int N>
  struct ProductTypeImpl<double, Sacado::Fad::SLFad<T, N>>
  {
    using type = Sacado::Fad::SLFad<T, N>;
  };

  template <typename T, typename U, int N>
  struct ProductTypeImpl<Sacado::Fad::SLFad<T, N>, Sacado::Fad::SLFad<U, N>>
  {
    using type = Sacado::Fad::SLFad<typename ProductType<T, U>::type, N>;
  };
} // namespace internal

template <typename T, int N>
struct EnableIfScalar<Sacado::Fad::SFad<T, N>>
{
  using type = Sacado::Fad::SFad<T, N>;
};

template <typename T, int N>
struct EnableIfScalar<Sacado::Fad::SLFad<T, N>>
{
  using type = Sacado::Fad::SLFad<T, N>;
};
DEAL_II_NAMESPACE_CLOSE

namespace ContactDynamics
{
  namespace ContactAD
  {
    /** Any number of derivatives (on the heap). */
    using AD = Sacado::Fad::DFad<double>;

    /**
     * At most `width` derivatives, on the stack: DFad allocates for every
     * temporary, which dominated the assembly. Operations run over the
     * actual number of derivatives, so that the values equal DFad's.
     */
    template <int width>
    using StaticAD = Sacado::Fad::SLFad<double, width>;

    /** The width of StaticAD that dispatch() uses. */
    constexpr unsigned int static_width = 32;

    /**
     * Calls f(Number()) with the number type for n independent variables:
     * StaticAD if they fit, else AD.
     */
    template <typename Function>
    void
    dispatch(const unsigned int n, const Function &f)
    {
      if (n <= static_width)
        f(StaticAD<static_width>());
      else
        f(AD());
    }

    /** The width of the static second derivatives of dispatch_second(). */
    constexpr unsigned int static_width_second = 24;

    /** Second derivatives in exactly n variables: loops of fixed length. */
    template <int n>
    using FixedAD2 = Sacado::Fad::SFad<Sacado::Fad::SFad<double, n>, n>;

    /**
     * Calls f(Number()) with a Fad of Fads for second derivatives in n
     * variables: of fixed length for the common patch sizes (their cost
     * grows with n^2, and the nested loops of variable length dominated),
     * static if they fit, else dynamic.
     */
    template <typename Function>
    void
    dispatch_second(const unsigned int n, const Function &f)
    {
      if (n == 12)
        f(FixedAD2<12>(0.));
      else if (n == 14)
        f(FixedAD2<14>(0.));
      else if (n == 16)
        f(FixedAD2<16>(0.));
      else if (n <= static_width_second)
        f(Sacado::Fad::SLFad<StaticAD<static_width_second>,
                             static_width_second>());
      else
        f(Sacado::Fad::DFad<AD>());
    }

    using SegmentGeometry::Vec;

    /** The value only: drops derivatives (approximate Jacobians). */
    template <typename Number>
    Number
    constant(const Number &x)
    {
      return Number(x.val());
    }

    template <typename Number>
    Vec<Number>
    constant(const Vec<Number> &x)
    {
      Vec<Number> c;
      for (unsigned int d = 0; d < 2; ++d)
        c[d] = constant(x[d]);
      return c;
    }

    template <typename Number>
    Vec<double>
    value(const Vec<Number> &x)
    {
      return Vec<double>({x[0].val(), x[1].val()});
    }

    /** Adds x (value and derivatives) to a linearized nodal quantity. */
    template <typename Number>
    void
    add_to(LinearizedValue                            &target,
           const Number                               &x,
           const std::vector<types::global_dof_index> &unknowns)
    {
      target.value += x.val();
      for (unsigned int k = 0; k < unknowns.size() && k < unsigned(x.size());
           ++k)
        if (x.dx(k) != 0)
          target.derivatives[unknowns[k]] += x.dx(k);
    }

    /** The nonzero derivatives of x with respect to the global unknowns. */
    template <typename Number>
    std::vector<std::pair<types::global_dof_index, double>>
    derivatives(const Number                               &x,
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
    template <int dim, typename Number>
    class NodeVariables
    {
    public:
      NodeVariables(const std::vector<types::global_dof_index> &unknowns,
                    const TrialState                           &state)
        : unknowns(unknowns)
        , state(state)
      {}

      template <int n_components>
      void
      add(const ContactSurface<dim>       &surface,
          const unsigned int               node,
          Tensor<1, n_components, Number> &x,
          Tensor<1, n_components, Number> &v)
      {
        static_assert(n_components <= dim);
        for (unsigned int d = 0; d < n_components; ++d, ++next)
          {
            Assert(unknowns[next] == surface.dofs[node][d], ExcInternalError());
            x[d] = Number(unknowns.size(),
                          next,
                          surface.reference[node][d] + state.u(unknowns[next]));
            // v = c_v u + (terms of the old state)
            v[d]       = state.c_v * x[d];
            v[d].val() = state.v(unknowns[next]);
          }
      }

      /** The next independent variable: a multiplier. */
      Number
      multiplier()
      {
        const unsigned int k = next++;
        return Number(unknowns.size(), k, state.u(unknowns[k]));
      }

    private:
      const std::vector<types::global_dof_index> &unknowns;
      const TrialState                           &state;
      unsigned int                                next = 0;
    };
  } // namespace ContactAD
} // namespace ContactDynamics

#endif
