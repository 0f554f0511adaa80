// The elastic bar impact of bar_impact.cc (exact: first contact at t =
// gap / v0 = 0.1, contact duration 2 L / c = 2, mean contact force rho c v0
// h, rebound velocity -v0, no energy lost) with generalized-alpha (rho_inf
// = 0.8) and HHT-alpha (rho_inf = 0.8) and mortar contact with persistency,
// whose held gap rates follow the scheme's beta and gamma. The contact
// must still create no energy (energy balance error, which now excludes
// the scheme's numerical dissipation, within 1 % of the initial energy),
// and the energy the scheme removes must stay small when the step resolves
// the wave (c dt / h = 0.5). A checkpoint written in contact and restarted
// must continue bitwise: the balance between the steps needs the committed
// forces F_n, which the checkpoint holds through the committed reactions.
// (The bar's momentum change is the sum of the balanced contact forces
// (1 - alpha_f) f_{n+1} + alpha_f f_n: were the contact forces missing
// from F_n, the reported forces f_{n+1} would add up to 1 / (1 - alpha_f) =
// 1.8 times the impulse, and the mean-force check would fail.)
#include <deal.II/dofs/dof_handler.h>

#include <contact_dynamics/output/checkpoint.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

using namespace dealii;

namespace
{
  const double dt = 0.0125, v0 = 0.1, h = 0.1;

  void
  read(const std::string &scheme, ParameterHandler &prm)
  {
    read_shipped("prm/examples/bar_impact.prm",
                 {{"Contact/Mortar/Stabilization", "persistency"},
                  {"Time integration/Scheme", scheme},
                  {"Time integration/Spectral radius at infinity", "0.8"},
                  {"Output/Output directory", "output_bar_" + scheme},
                  {"Output/VTU interval", "0"}},
                 prm);
  }

  void
  check_scheme(const std::string &scheme)
  {
    deallog << scheme << std::endl;
    ParameterHandler prm;
    read(scheme, prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    const double initial = simulator.energy().initial;
    double       first = -1, last = -1, impulse = 0;
    bool         written = false;
    while (simulator.current_time() < 3 - 1e-9)
      {
        if (!simulator.advance(dt))
          check_true("step converged", false);
        const auto stats = contact_statistics(*simulator.get_contact());
        impulse += stats.at("contact_force_x") * dt;
        if (stats.at("active_contact_nodes") > 0)
          {
            if (first < 0)
              first = simulator.current_time();
            last = simulator.current_time();
          }
        if (!written && simulator.current_time() > 1 - 1e-9)
          {
            simulator.write_checkpoint();
            written = true;
          }
      }
    const double duration = last - first + dt;
    const auto  &e        = simulator.energy();
    check_close("first contact at gap / v0", first, 0.1, dt);
    check_close("contact duration 2 L / c", duration, 2., 2 * dt);
    check_close("mean contact force / (rho c v0 h)",
                -impulse / duration / (v0 * h),
                1.,
                0.03);
    check_close("rebound velocity / v0",
                mean_velocity_x(simulator, 0) / v0,
                -1.,
                0.02);
    check_close("contact work (energy balance error) / initial energy",
                e.error() / initial,
                0.,
                0.01);
    check_range("numerical dissipation / initial energy",
                e.numerical / initial,
                0.,
                0.02);
    deallog << std::setprecision(3) << "  energy after / before - 1 = "
            << (e.kinetic + e.elastic) / initial - 1
            << ", numerical dissipation / initial energy = "
            << e.numerical / initial << std::endl;

    // the run again from its checkpoint at t = 1, in contact
    ParameterHandler prm2;
    read(scheme, prm2);
    ContactDynamics::Simulator<2> restarted(prm2, screen);
    restarted.restart(
      ContactDynamics::Checkpoints::find("output_bar_" + scheme));
    check_close("restarted at t = 1", restarted.current_time(), 1., 1e-9);
    while (restarted.current_time() < 3 - 1e-9)
      if (!restarted.advance(dt))
        check_true("restarted step converged", false);
    Vector<double> difference(simulator.displacement().size());
    for (const auto i : simulator.displacement().locally_owned_elements())
      difference[i] = simulator.displacement()(i) - restarted.displacement()(i);
    check_close("restarted: displacement at t = 3 (max difference)",
                difference.linfty_norm(),
                0.,
                0.);
    check_close("restarted: numerical dissipation at t = 3 (difference)",
                restarted.energy().numerical - e.numerical,
                0.,
                0.);
  }
} // namespace

int
main()
{
  initlog();
  check_scheme("generalized-alpha");
  check_scheme("hht-alpha");
}
