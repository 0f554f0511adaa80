// Persistency on a curved sliding interface: the ironing tool (a circular
// arc, half the shipped mesh density) indents the substrate by 0.2 in 0.4 s
// while sliding at unit speed, then slides frictionlessly at constant depth
// until 1 s (about 5 substrate elements).
// - 'persistency': from the end of its first held step (which still moves
//   it by dt/2 times the gap rate it was captured with: the trapezoidal
//   rule) the normalized weighted gap of every held node stays within 1e-6
//   of that value;
// - frictionless contact does no work while sliding: the contact work over
//   the sliding phase is below 0.1 % of the external work done on the
//   bodies;
// - the paper's velocity-level persistency drifts (its held gaps change by
//   more than 1e-4) and removes at least 10 times more energy while
//   sliding;
// - the nodal pressure along the contact zone is not rougher (RMS of the
//   second difference over the mean) than with static mortar.
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <algorithm>
#include <cmath>

using namespace dealii;

namespace
{
  using Mortar = ContactDynamics::MortarContact<2>;

  struct Outcome
  {
    double       drift         = 0; // largest change of a held gap
    unsigned int held_steps    = 0; // node-steps checked
    double       sliding_work  = 0; // contact work over the sliding phase
    double       external_work = 0; // at the end
    double       roughness     = 0; // of the pressure at the end
    unsigned int newton        = 0;
  };

  Outcome
  run(const std::string &stabilization)
  {
    ParameterHandler prm;
    ContactDynamics::read_parameters(std::string(SOURCE_DIR) +
                                       "/../prm/ironing/mortar.prm",
                                     prm);
    const auto set = [&](const std::string &section,
                         const std::string &entry,
                         const std::string &value) {
      const auto sections = Utilities::split_string_list(section, '/');
      for (const auto &s : sections)
        prm.enter_subsection(s);
      prm.set(entry, value);
      for (unsigned int i = 0; i < sections.size(); ++i)
        prm.leave_subsection();
    };
    set("Scene", "Refinement factor", "0.5");
    set("Boundary conditions",
        "Dirichlet",
        "substrate_bottom: xy: 0; tool_top: x: t; tool_top: y: "
        "if(t <= 0.4, -t/2, -0.2)");
    std::string directory = "output_" + stabilization;
    std::replace(directory.begin(), directory.end(), ' ', '_');
    set("Output", "Output directory", directory);
    set("Output", "VTU interval", "0");
    set("Contact/Mortar", "Stabilization", stabilization);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();

    const auto &mortar = *dynamic_cast<const Mortar *>(simulator.get_contact());
    const unsigned int  n = mortar.node_states(0).size();
    std::vector<double> held_value(n, 0.);
    std::vector<int>    held_for(n, 0); // steps held in a row
    std::vector<bool>   persistent_before(n, false);
    Outcome             outcome;
    double              work_at_sliding = 0;
    for (unsigned int step = 1; step <= 100; ++step)
      {
        if (!simulator.advance(0.01))
          {
            check_true(stabilization + ": every step converges", false);
            return outcome;
          }
        const auto &nodes = mortar.node_states(0);
        for (unsigned int j = 0; j < n; ++j)
          {
            // held in this step: persistent after the previous commit, and
            // still in contact
            const bool held = persistent_before[j] && nodes[j].active;
            held_for[j]     = held ? held_for[j] + 1 : 0;
            if (held_for[j] == 1)
              held_value[j] = nodes[j].normalized_gap();
            else if (held_for[j] > 1)
              {
                outcome.drift =
                  std::max(outcome.drift,
                           std::abs(nodes[j].normalized_gap() - held_value[j]));
                ++outcome.held_steps;
              }
            persistent_before[j] = nodes[j].persistent;
          }
        if (step == 50)
          work_at_sliding =
            contact_statistics(*simulator.get_contact()).at("contact_work");
      }
    outcome.sliding_work =
      contact_statistics(*simulator.get_contact()).at("contact_work") -
      work_at_sliding;
    const auto columns    = read_csv_columns(directory + "/statistics.csv");
    outcome.external_work = columns.at("external_work").back();
    outcome.newton        = columns.at("cumulative_newton_iterations").back();

    // pressure along the contact zone, ordered along the surface
    std::vector<std::pair<double, double>> zone;
    const auto                            &nodes = mortar.node_states(0);
    const auto secondary                         = mortar.secondary_nodes(0);
    for (unsigned int j = 0; j < n; ++j)
      if (nodes[j].active)
        zone.emplace_back(secondary.position[j][0], nodes[j].pressure);
    std::sort(zone.begin(), zone.end());
    double mean = 0, second = 0;
    for (const auto &z : zone)
      mean += z.second / zone.size();
    for (unsigned int i = 1; i + 1 < zone.size(); ++i)
      second +=
        std::pow(zone[i - 1].second - 2 * zone[i].second + zone[i + 1].second,
                 2) /
        (zone.size() - 2);
    outcome.roughness = std::sqrt(second) / mean;
    deallog << stabilization << ": " << zone.size()
            << " nodes in contact at t = 1" << std::endl;
    return outcome;
  }
} // namespace

int
main()
{
  initlog();
  const Outcome exact    = run("persistency");
  const Outcome velocity = run("velocity persistency");
  const Outcome none     = run("none");

  check_true("persistency: held nodes checked", exact.held_steps > 500);
  check_true("persistency: held gaps within 1e-6 of their value",
             exact.drift < 1e-6);
  check_true("persistency: sliding contact work below 0.1 % of the external "
             "work",
             std::abs(exact.sliding_work) < 1e-3 * exact.external_work);
  check_true("velocity persistency: held gaps drift by more than 1e-4",
             velocity.drift > 1e-4);
  check_true("velocity persistency: at least 10 times the sliding work",
             std::abs(velocity.sliding_work) >
               10 * std::abs(exact.sliding_work));
  check_true("persistency: pressure no rougher than static mortar's",
             exact.roughness <= none.roughness);
  // the measured figures, for doc/contact.md
  std::cout << "drift " << exact.drift << " / " << velocity.drift
            << ", sliding work " << exact.sliding_work << " / "
            << velocity.sliding_work << " / " << none.sliding_work
            << ", external work " << exact.external_work << ", roughness "
            << exact.roughness << " / " << velocity.roughness << " / "
            << none.roughness << ", Newton " << exact.newton << " / "
            << velocity.newton << " / " << none.newton << std::endl;
}
