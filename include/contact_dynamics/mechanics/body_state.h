// The state of the bodies that outlives a time step, and what the Simulator
// tells the owners of its history (include/contact_dynamics/history.h).
#ifndef contact_dynamics_mechanics_body_state_h
#define contact_dynamics_mechanics_body_state_h

#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/history.h>

#include <string>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;
  using VectorType = TrilinosWrappers::MPI::Vector;

  /** What the Simulator passes to every owner of its history. */
  struct RunContext
  {
    /** The checkpoint directory of a load() (for messages), else "". */
    std::string checkpoint;
  };

  /**
   * The displacement, velocity and acceleration of the committed state at
   * t_n with its bulk forces (the reactions of the trapezoidal external
   * work), and the trial state at t_{n+1} the Newton iteration works on.
   * The trial vectors are scratch between the steps: commit() swaps them
   * with the committed ones. The Simulator sets their layout (setup).
   */
  class BodyState : public HistoryOwner<RunContext>
  {
  public:
    std::string
    name() const override
    {
      return "body state";
    }

    void
    commit(const RunContext &) override
    {
      u.swap(u_new);
      v.swap(v_new);
      a.swap(a_new);
      residual_full_old.swap(residual_full);
    }

    /** Only vectors: list_vectors(). */
    void
    save(CheckpointData &, const RunContext &) const override
    {}

    void
    load(const CheckpointData &, const RunContext &) override
    {}

    /** The committed state and its forces, in checkpoint order. */
    void
    list_vectors(std::vector<VectorType *> &vectors) override
    {
      for (VectorType *x : {&u, &v, &a, &residual_full_old})
        vectors.push_back(x);
    }

    /**
     * The committed state and the trial displacement of the step (its
     * forces are evaluated again).
     */
    void
    prepare_transfer(std::vector<VectorType *> &vectors) override
    {
      for (VectorType *x : {&u, &v, &a, &u_new})
        vectors.push_back(x);
    }

    // committed at t_n, and the bulk forces of that state
    VectorType u, v, a, residual_full_old;
    // the trial state at t_{n+1} and the forces of its last assembly
    VectorType u_new, v_new, a_new, residual_full;
    // generalized-alpha and HHT: the forces F_n of the committed state
    // (residual_full_old without M a_n) and the balanced acceleration
    VectorType force_old, effective_acceleration;
  };
} // namespace ContactDynamics

#endif
