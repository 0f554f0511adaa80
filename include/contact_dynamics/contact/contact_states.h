// What a contact formulation is told about the trial state and what it
// reports about its secondary nodes.
#ifndef contact_dynamics_contact_contact_states_h
#define contact_dynamics_contact_contact_states_h

#include <deal.II/base/point.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/contact/contact_history.h>
#include <contact_dynamics/mechanics/time_integrator.h>

#include <array>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;
  using VectorType = TrilinosWrappers::MPI::Vector;
  using MatrixType = TrilinosWrappers::SparseMatrix;

  /** What the time integrator tells a formulation about the trial state. */
  struct TrialState
  {
    const VectorType     &u;       // displacement (and multipliers) at t_{n+1}
    const VectorType     &v;       // Newmark velocity at t_{n+1}
    double                c_v;     // d v / d u
    double                dt;      // time step size
    bool                  dynamic; // false for quasi-static
    const TimeIntegrator &integrator; // for the rates of nodal quantities
  };

  /** The state of a secondary node after an assembly. */
  struct ContactNodeState
  {
    double gap      = 0; // weighted (mortar) or pointwise gap
    double weight   = 0; // its normalization; 0: no projection
    double pressure = 0; // lambda_n
    // lambda_t (friction) and the normalized relative tangential velocity
    // along the node's tangents (one in 2-D, two in 3-D)
    std::array<double, 2> tangential = {{0., 0.}};
    std::array<double, 2> slip_rate  = {{0., 0.}};
    bool                  projected  = false;
    bool                  active     = false;
    bool                  stick      = false; // active and sticking (friction)
    bool persistent = false; // holds its gap (rate) in the next step
    // the normalized gap's Newmark rate and second rate at this state, and
    // the normalized gap with its rates at the last committed step
    double gap_rate = 0, gap_acceleration = 0;
    // the velocity-level rate -int psi (v_s - v_p).n / w at this state
    double velocity_rate = 0;
    double held_gap = 0, held_rate = 0, held_acceleration = 0;

    /** The gap in length units. */
    double
    normalized_gap() const
    {
      return projected ? gap / weight : 0.;
    }
  };

  /** The secondary nodes of a contact pair, for the output. */
  template <int dim>
  struct SecondaryNodes
  {
    const std::vector<Point<dim>> &reference;
    // at the last committed step (the reference ones before the first)
    const std::vector<Point<dim>>       &position;
    const std::vector<ContactNodeState> &states;
    // what owners of history add per node (ContactHistoryOwner)
    std::vector<NodeColumn> columns = {};
  };

} // namespace ContactDynamics

#endif
