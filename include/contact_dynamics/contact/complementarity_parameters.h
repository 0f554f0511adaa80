// The parameters of the nonlinear complementarity conditions that the
// contact formulations with nodal multipliers solve, and the linearized
// values (gaps, weights, rates) the conditions are assembled from.
#ifndef contact_dynamics_contact_complementarity_parameters_h
#define contact_dynamics_contact_complementarity_parameters_h

#include <deal.II/base/types.h>

#include <map>

DEAL_II_NAMESPACE_OPEN
class ParameterHandler;
DEAL_II_NAMESPACE_CLOSE

namespace ContactDynamics
{
  using namespace dealii;

  /** Parameters of the complementarity condition, per formulation. */
  struct ComplementarityParameters
  {
    /** What keeps a node that is in contact from creating energy. */
    enum class Stabilization
    {
      none,                 // the gap is enforced at every step (static)
      persistency,          // Newmark rate of the weighted gap held at zero
      velocity_persistency, // the paper's velocity-level gap rate
      velocity_update       // static, then a velocity correction
    };

    double        c_n           = 1e6;
    bool          normalize_c_n = true;
    Stabilization stabilization;
    double        capture_tolerance = 1e-5;
    // a node's first held step keeps its captured gap (no dt/2 sinking)
    bool   capture_at_position = false;
    bool   exact_jacobian      = true;
    double c_t                 = 1e4;

    /** The formulations differ in the default stabilization only. */
    explicit ComplementarityParameters(
      const Stabilization stabilization = Stabilization::persistency)
      : stabilization(stabilization)
    {}

    /** Whether a node in contact holds its gap (rate) in the next step. */
    bool
    holds_contact() const
    {
      return stabilization != Stabilization::none;
    }

    /** Declares the entries with the values of `defaults` as defaults. */
    static void
    declare_parameters(ParameterHandler                &prm,
                       const ComplementarityParameters &defaults);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** A value and its derivatives with respect to global unknowns. */
  struct LinearizedValue
  {
    double                                    value = 0;
    std::map<types::global_dof_index, double> derivatives;
  };
} // namespace ContactDynamics

#endif
