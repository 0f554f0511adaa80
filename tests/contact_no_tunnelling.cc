// A bar (L = 1, E = rho = 1, nu = 0, so c = 1) hits a clamped wall across a
// gap of 0.01 at v0 = 10 and v0 = 100 with time steps of 0.0125: it moves
// 5 and 50 elements (h = 0.025) per step, and its contact face passes the
// whole wall (0.2 thick) in one step at v0 = 100. A search around the
// trial configuration only never sees the wall (the bar went through it
// with no active node); the swept search must find the contact in the first
// step, and the bar must rebound. The problem is linear in v0 apart from
// the impact phase within a step (the contact face is straight and moves
// along x): the 1-D solution is a rebound at -v0 after 2 L / c.
#include <deal.II/dofs/dof_handler.h>

#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <chrono>
#include <fstream>

using namespace dealii;

namespace
{
  struct Result
  {
    double       first_contact = -1; // time of the first active node
    double       last_contact  = -1;
    double       max_face_x    = -1e300; // contact face, over all steps
    double       rebound       = 0;      // mean striker velocity at the end
    unsigned int cuts          = 0;
    unsigned int steps         = 0;
    double       energy_error  = 0; // (kinetic + elastic) / initial - 1
  };


  // the elastic bar impact of prm/examples/bar_impact.prm at speed v0
  void
  read_bar(const double       v0,
           const std::string &stabilization,
           ParameterHandler  &prm)
  {
    read_shipped("prm/examples/bar_impact.prm",
                 {{"Body striker/Initial velocity", std::to_string(v0) + "; 0"},
                  {"Contact/Mortar/Stabilization", stabilization},
                  {"Output/Output directory", "output_tunnel"},
                  {"Output/VTU interval", "0"}},
                 prm);
  }

  Result
  run(const double       v0,
      const double       end_time,
      const std::string &stabilization = "persistency")
  {
    const double     dt = 0.0125;
    ParameterHandler prm;
    read_bar(v0, stabilization, prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    Result result;
    // the time step control of Simulator::run
    double       step      = dt;
    unsigned int good_runs = 0;
    while (simulator.current_time() < end_time - 1e-9)
      {
        const double try_step =
          std::min(step, end_time - simulator.current_time());
        if (!simulator.advance(try_step))
          {
            ++result.cuts;
            step /= 2;
            good_runs = 0;
            AssertThrow(step > 1e-6, ExcMessage("time step too small"));
            continue;
          }
        if (step < dt && ++good_runs >= 2)
          {
            step      = std::min(2 * step, dt);
            good_runs = 0;
          }
        ++result.steps;
        const auto &contact = *simulator.get_contact();
        const auto  stats   = contact_statistics(contact);
        if (stats.at("active_contact_nodes") > 0)
          {
            if (result.first_contact < 0)
              result.first_contact = simulator.current_time();
            result.last_contact = simulator.current_time();
          }
        // committed positions of the striker's contact face
        for (const auto &x : contact.secondary_nodes(0).position)
          result.max_face_x = std::max(result.max_face_x, x[0]);
      }
    result.rebound      = mean_velocity_x(simulator, 0);
    const auto &e       = simulator.energy();
    result.energy_error = (e.kinetic + e.elastic) / e.initial - 1;
    return result;
  }

  // The wrong-side check on a state it must reject: from the initial state
  // (the striker 0.01 before the wall, no active node) a trial state with
  // the striker moved by 0.3, its contact face through the whole wall.
  std::string
  check_through_wall()
  {
    ParameterHandler prm;
    read_bar(10, "persistency", prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    TrilinosWrappers::MPI::Vector u(simulator.displacement());
    for (const auto &cell : simulator.get_dof_handler().active_cell_iterators())
      if (cell->material_id() == 0)
        for (unsigned int v = 0; v < 4; ++v)
          u(cell->vertex_dof_index(v, 0)) = 0.3;
    u.compress(VectorOperation::insert);
    return simulator.get_contact()->check_step(u);
  }
} // namespace

int
main()
{
  initlog();
  const double      dt = 0.0125, h = 0.025; // h: element size of both bodies
  const std::string message = check_through_wall();
  check_true("a node through the wall is reported, naming the pair",
             message.find("contact pair 'striker_right: target_left'") !=
                 std::string::npos &&
               message.find("went through the primary face") !=
                 std::string::npos);
  for (const double v0 : {10., 100.})
    {
      const std::string name  = "v0 = " + std::to_string(int(v0)) + ": ";
      const auto        start = std::chrono::steady_clock::now();
      // contact lasts 2 L / c = 2 from gap / v0 < dt on
      const Result r = run(v0, 2.2);
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      check_close(name + "contact found in the first step",
                  r.first_contact,
                  dt,
                  1e-12);
      check_close(name + "contact ends after 2 L / c", r.last_contact, 2., 0.1);
      // a held node may not sink by more than half an element (the step
      // is cut otherwise), so the face never passes the wall
      check_true(name + "contact face at most h / 2 behind the wall face",
                 r.max_face_x <= h / 2 + 1e-12);
      // the 1-D solution rebounds at -v0; with dt v0 of 5 and 50 elements
      // the contact node chatters (the step is cut at every recapture), and
      // 5 % allows for that (the resolved impact of bar_impact keeps 2 %)
      check_close(name + "rebound velocity / v0", r.rebound / v0, -1., 0.05);
      // persistency: the chattering contact node does work (measured: the
      // energy ends 1 % above the initial one at v0 = 10 and 3.9 times it
      // at v0 = 100); the velocity update returns it at every step
      const Result u = run(v0, 2.2, "velocity update");
      check_close(name + "velocity update: contact found in the first step",
                  u.first_contact,
                  dt,
                  1e-12);
      check_close(name + "velocity update: energy kept to 1e-6",
                  u.energy_error,
                  0.,
                  1e-6);
      // (at v0 = 100 part of the kept energy stays in the striker's
      // vibration: measured mean rebound -0.76 v0)
      check_true(name + "velocity update: the striker rebounds (mean "
                        "velocity below -v0 / 2)",
                 u.rebound / v0 < -0.5);
      std::cout << name << "max face x " << r.max_face_x << ", rebound / v0 "
                << r.rebound / v0 << ", last contact " << r.last_contact << ", "
                << r.steps << " steps, " << r.cuts << " cuts, energy error "
                << r.energy_error << ", " << seconds
                << " s; velocity update: energy error " << u.energy_error
                << ", rebound / v0 " << u.rebound / v0 << ", " << u.cuts
                << " cuts" << std::endl;
    }
}
