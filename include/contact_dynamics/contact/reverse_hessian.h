// Second derivatives of one scalar by reverse over forward mode: every
// operation on a ReverseHessian::Number computes its value with the first
// derivatives in N inputs (a Sacado SFad) and records itself on a tape; one
// reverse sweep of the tape in SFad arithmetic (reverse_hessian_sweep.h)
// then gives the gradient of the scalar and its Hessian (Griewank and Walther,
// "Evaluating derivatives", 2nd ed., SIAM 2008, ch. 5). A Fad of Fads costs N
// times a first-order pass for the whole Hessian of every output; this costs a
// few first-order passes for the Hessian of one weighted sum of the outputs,
// which is all the 3-D mortar Jacobian needs (mortar_face_3d_hessian.cc). The
// tape is per thread; one function is taped at a time (start() to the sweep).
#ifndef contact_dynamics_contact_reverse_hessian_h
#define contact_dynamics_contact_reverse_hessian_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/template_constraints.h>

#include <Sacado_Fad_SFad.hpp>
#include <cmath>
#include <vector>

namespace ContactDynamics
{
  namespace ReverseHessian
  {
    enum class Op : unsigned char
    {
      independent,
      add,      // a + b
      subtract, // a - b
      multiply, // a * b
      divide,   // a / b
      add_constant,
      scale,               // a * c
      constant_minus,      // c - a
      constant_divided_by, // c / a
      negate,
      square_root
    };

    template <typename Inner>
    struct Node
    {
      Op     op;
      int    a, b;
      double c;
      Inner  value;
    };

    template <typename Inner>
    std::vector<Node<Inner>> &
    tape()
    {
      thread_local std::vector<Node<Inner>> nodes;
      return nodes;
    }

    /**
     * A node of the tape (index >= 0) or a constant c (index -1); the
     * node's value carries the first derivatives in the N inputs. Small, so
     * that the geometry code copies it freely.
     */
    template <typename Inner>
    class Number
    {
    public:
      using value_type = Inner;

      Number(const double c = 0.)
        : index(-1)
        , c(c)
      {}

      /** Input k of n with value x (on the tape). */
      static Number
      independent(const double x, const int k, const int n)
      {
        return record(Op::independent, -1, -1, 0., [&](Inner &v) {
          v = Inner(n, k, x);
        });
      }

      /**
       * Appends a node and sets its value by `compute` (which may read the
       * values of earlier nodes: the tape does not move meanwhile).
       */
      template <typename Compute>
      static Number
      record(const Op       op,
             const int      a,
             const int      b,
             const double   c,
             const Compute &compute)
      {
        auto &t = tape<Inner>();
        if (t.size() == t.capacity())
          t.reserve(2 * t.size() + 4096);
        t.emplace_back();
        Node<Inner> &node = t.back();
        node.op           = op;
        node.a            = a;
        node.b            = b;
        node.c            = c;
        compute(node.value);
        Number r;
        r.index = static_cast<int>(t.size()) - 1;
        return r;
      }

      const Inner &
      value() const
      {
        Assert(index >= 0, dealii::ExcInternalError());
        return tape<Inner>()[index].value;
      }

      Inner
      val() const
      {
        return index < 0 ? Inner(c) : value();
      }

      Number &
      operator+=(const Number &o)
      {
        return *this = *this + o;
      }
      Number &
      operator-=(const Number &o)
      {
        return *this = *this - o;
      }
      Number &
      operator*=(const Number &o)
      {
        return *this = *this * o;
      }
      Number &
      operator/=(const Number &o)
      {
        return *this = *this / o;
      }
      Number
      operator-() const
      {
        if (index < 0)
          return Number(-c);
        return record(Op::negate, index, -1, 0., [&](Inner &v) {
          v = -value();
        });
      }

      int    index;
      double c;
    };

    template <typename Inner>
    double
    value_of(const Number<Inner> &x)
    {
      return x.index < 0 ? x.c : x.value().val();
    }

    template <typename Inner>
    Number<Inner>
    operator+(const Number<Inner> &x, const Number<Inner> &y)
    {
      if (x.index < 0 && y.index < 0)
        return Number<Inner>(x.c + y.c);
      if (x.index < 0 || y.index < 0)
        {
          const Number<Inner> &z = x.index < 0 ? y : x;
          const double         c = x.index < 0 ? x.c : y.c;
          return Number<Inner>::record(Op::add_constant,
                                       z.index,
                                       -1,
                                       c,
                                       [&](Inner &v) {
                                         v = z.value() + c;
                                       });
        }
      return Number<Inner>::record(Op::add,
                                   x.index,
                                   y.index,
                                   0.,
                                   [&](Inner &v) {
                                     v = x.value() + y.value();
                                   });
    }

    template <typename Inner>
    Number<Inner>
    operator-(const Number<Inner> &x, const Number<Inner> &y)
    {
      if (x.index < 0 && y.index < 0)
        return Number<Inner>(x.c - y.c);
      if (x.index < 0)
        return Number<Inner>::record(Op::constant_minus,
                                     y.index,
                                     -1,
                                     x.c,
                                     [&](Inner &v) {
                                       v = x.c - y.value();
                                     });
      if (y.index < 0)
        return Number<Inner>::record(Op::add_constant,
                                     x.index,
                                     -1,
                                     -y.c,
                                     [&](Inner &v) {
                                       v = x.value() - y.c;
                                     });
      return Number<Inner>::record(Op::subtract,
                                   x.index,
                                   y.index,
                                   0.,
                                   [&](Inner &v) {
                                     v = x.value() - y.value();
                                   });
    }

    template <typename Inner>
    Number<Inner>
    operator*(const Number<Inner> &x, const Number<Inner> &y)
    {
      if (x.index < 0 && y.index < 0)
        return Number<Inner>(x.c * y.c);
      if (x.index < 0 || y.index < 0)
        {
          const Number<Inner> &z = x.index < 0 ? y : x;
          const double         c = x.index < 0 ? x.c : y.c;
          return Number<Inner>::record(Op::scale,
                                       z.index,
                                       -1,
                                       c,
                                       [&](Inner &v) {
                                         v = c * z.value();
                                       });
        }
      return Number<Inner>::record(Op::multiply,
                                   x.index,
                                   y.index,
                                   0.,
                                   [&](Inner &v) {
                                     v = x.value() * y.value();
                                   });
    }

    template <typename Inner>
    Number<Inner>
    operator/(const Number<Inner> &x, const Number<Inner> &y)
    {
      if (x.index < 0 && y.index < 0)
        return Number<Inner>(x.c / y.c);
      if (x.index < 0)
        return Number<Inner>::record(Op::constant_divided_by,
                                     y.index,
                                     -1,
                                     x.c,
                                     [&](Inner &v) {
                                       v = x.c / y.value();
                                     });
      if (y.index < 0)
        return Number<Inner>::record(Op::scale,
                                     x.index,
                                     -1,
                                     1. / y.c,
                                     [&](Inner &v) {
                                       v = x.value() / y.c;
                                     });
      return Number<Inner>::record(Op::divide,
                                   x.index,
                                   y.index,
                                   0.,
                                   [&](Inner &v) {
                                     v = x.value() / y.value();
                                   });
    }

#define CONTACT_DYNAMICS_REVERSE_HESSIAN_MIXED(op)                  \
  template <typename Inner>                                         \
  Number<Inner> operator op(const Number<Inner> &x, const double y) \
  {                                                                 \
    return x op Number<Inner>(y);                                   \
  }                                                                 \
  template <typename Inner>                                         \
  Number<Inner> operator op(const double x, const Number<Inner> &y) \
  {                                                                 \
    return Number<Inner>(x) op y;                                   \
  }
    CONTACT_DYNAMICS_REVERSE_HESSIAN_MIXED(+)
    CONTACT_DYNAMICS_REVERSE_HESSIAN_MIXED(-)
    CONTACT_DYNAMICS_REVERSE_HESSIAN_MIXED(*)
    CONTACT_DYNAMICS_REVERSE_HESSIAN_MIXED(/)
#undef CONTACT_DYNAMICS_REVERSE_HESSIAN_MIXED

    template <typename Inner>
    Number<Inner>
    sqrt(const Number<Inner> &x)
    {
      using std::sqrt;
      if (x.index < 0)
        return Number<Inner>(sqrt(x.c));
      return Number<Inner>::record(Op::square_root,
                                   x.index,
                                   -1,
                                   0.,
                                   [&](Inner &v) {
                                     v = sqrt(x.value());
                                   });
    }

    /** Empties the tape: the numbers recorded so far must not be used. */
    template <typename Inner>
    void
    start()
    {
      tape<Inner>().clear();
    }
  } // namespace ReverseHessian
} // namespace ContactDynamics

DEAL_II_NAMESPACE_OPEN
namespace internal
{
  template <typename Inner>
  struct ProductTypeImpl<ContactDynamics::ReverseHessian::Number<Inner>,
                         ContactDynamics::ReverseHessian::Number<Inner>>
  {
    using type = ContactDynamics::ReverseHessian::Number<Inner>;
  };

  template <typename Inner>
  struct ProductTypeImpl<ContactDynamics::ReverseHessian::Number<Inner>, double>
  {
    using type = ContactDynamics::ReverseHessian::Number<Inner>;
  };

  template <typename Inner>
  struct ProductTypeImpl<double, ContactDynamics::ReverseHessian::Number<Inner>>
  {
    using type = ContactDynamics::ReverseHessian::Number<Inner>;
  };
} // namespace internal

template <typename Inner>
struct EnableIfScalar<ContactDynamics::ReverseHessian::Number<Inner>>
{
  using type = ContactDynamics::ReverseHessian::Number<Inner>;
};
DEAL_II_NAMESPACE_CLOSE

#endif
