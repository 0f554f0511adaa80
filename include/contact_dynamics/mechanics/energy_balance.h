// The energy account of a run: the terms of the discrete energy balance.
#ifndef contact_dynamics_mechanics_energy_balance_h
#define contact_dynamics_mechanics_energy_balance_h

namespace ContactDynamics
{
  /** Energies of the discrete system; see doc/theory.md. */
  struct EnergyBalance
  {
    double kinetic    = 0;
    double elastic    = 0;
    double dissipated = 0; // time integral of v.C v
    double external   = 0; // work of reactions and body forces
    double initial    = 0; // kinetic + elastic at t = 0
    double frictional = 0; // dissipated by contact friction
    double obstacle   = 0; // work of moving rigid obstacles on the bodies
    double transfer   = 0; // energy change of the mesh transfers
    // removed by the time integrator from the bulk (dissipative schemes)
    double numerical = 0;

    double
    error() const
    {
      return kinetic + elastic + dissipated + frictional + numerical -
             external - obstacle - transfer - initial;
    }
  };
} // namespace ContactDynamics

#endif
