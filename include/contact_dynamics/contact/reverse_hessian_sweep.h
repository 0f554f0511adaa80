// The reverse sweep of a ReverseHessian tape (reverse_hessian.h): the
// adjoints of all nodes in the first-order arithmetic of the tape's values,
// so that one sweep gives the gradient and the Hessian of one scalar.
#ifndef contact_dynamics_contact_reverse_hessian_sweep_h
#define contact_dynamics_contact_reverse_hessian_sweep_h

#include <contact_dynamics/contact/reverse_hessian.h>

#include <vector>

namespace ContactDynamics
{
  namespace ReverseHessian
  {

    /**
     * The reverse sweep from y: adjoint[k] of the tape's node k is dy/dv_k
     * with its first derivatives in the inputs, so that, for input i,
     * (*this)(x_i).val() = dy/dx_i and (*this)(x_i).dx(l) = d^2 y/dx_i dx_l.
     * Adjoints are set on their first contribution (no zero fill) and
     * nodes that do not reach y are skipped. One sweep per thread at a
     * time: the adjoints' buffer is shared.
     */
    template <typename Inner>
    class Sweep
    {
    public:
      explicit Sweep(const Number<Inner> &y)
        : adjoint(buffer())
      {
        const auto &t = tape<Inner>();
        AssertThrow(y.index >= 0,
                    dealii::ExcMessage("ReverseHessian::Sweep of a constant"));
        if (adjoint.size() < t.size())
          adjoint.resize(t.size());
        reached.assign(t.size(), 0);
        adjoint[y.index] = Inner(1.);
        reached[y.index] = 1;
        for (int k = y.index; k >= 0; --k)
          if (reached[k])
            propagate(t, k);
      }

      /** dy/dx with its first derivatives (zero if x does not reach y). */
      Inner
      operator()(const Number<Inner> &x) const
      {
        return x.index >= 0 && reached[x.index] ? adjoint[x.index] : Inner(0.);
      }

    private:
      template <typename Expr>
      void
      add(const int i, const Expr &e)
      {
        if (reached[i])
          adjoint[i] += e;
        else
          {
            adjoint[i] = e;
            reached[i] = 1;
          }
      }

      void
      propagate(const std::vector<Node<Inner>> &t, const int k)
      {
        const Node<Inner> &node = t[k];
        const Inner       &w    = adjoint[k];
        switch (node.op)
          {
            case Op::independent:
              break;
            case Op::add:
              add(node.a, w);
              add(node.b, w);
              break;
            case Op::subtract:
              add(node.a, w);
              add(node.b, -w);
              break;
            case Op::multiply:
              add(node.a, w * t[node.b].value);
              add(node.b, w * t[node.a].value);
              break;
            case Op::divide:
              {
                const Inner q = w / t[node.b].value;
                add(node.a, q);
                add(node.b, -q * node.value);
                break;
              }
            case Op::add_constant:
              add(node.a, w);
              break;
            case Op::scale:
              add(node.a, node.c * w);
              break;
            case Op::constant_minus:
            case Op::negate:
              add(node.a, -w);
              break;
            case Op::constant_divided_by:
              add(node.a, -w * node.value / t[node.a].value);
              break;
            case Op::square_root:
              add(node.a, w / (2. * node.value));
              break;
          }
      }

      // (reused: a fresh vector of a few MB costs page faults per sweep)
      static std::vector<Inner> &
      buffer()
      {
        thread_local std::vector<Inner> b;
        return b;
      }

      std::vector<Inner>        &adjoint;
      std::vector<unsigned char> reached;
    };
  } // namespace ReverseHessian
} // namespace ContactDynamics

#endif
