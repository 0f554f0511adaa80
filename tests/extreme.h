// The extreme-case check (issue 7): a case either completes with bounded
// energy and finite numbers, or stops with a message that names the
// problem and keeps the steps completed so far.
#ifndef contact_dynamics_tests_extreme_h
#define contact_dynamics_tests_extreme_h

#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <algorithm>
#include <cmath>

struct ExtremeCase
{
  std::string                                      name;
  std::string                                      file; // shipped .prm
  std::vector<std::pair<std::string, std::string>> changes;
  double                                           end_time;
  // the entry a stop message must name
  std::string expected_entry = "Minimum time step";
  // energy created beyond the external work, as a fraction of the largest
  // total energy
  double energy_tolerance = 1e-4;
};

// Energy created beyond the external work may be at most
// ExtremeCase::energy_tolerance of the largest total energy (by default
// 1e-4: Newmark's trapezoidal error on neo-Hookean work is 5e-5 of it in
// the bouncing block).

// Checks a case and appends "name,outcome,t_end,steps,cuts,excess,message" to
// outcomes.csv (for doc/extreme-cases.md); deallog gets only the robust
// part: the outcome and the checks.
inline void
check_extreme_case(const ExtremeCase &c)
{
  std::string directory = "output_";
  for (const char ch : c.name)
    directory += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  auto changes = c.changes;
  changes.push_back({"Output/Output directory", directory});
  changes.push_back({"Output/VTU interval", "0"});
  changes.push_back({"Time integration/End time", std::to_string(c.end_time)});
  std::string error;
  const auto  s =
    run_shipped<ContactDynamics::Simulator<2>>(c.file, changes, {}, &error);

  bool finite = true;
  for (const auto &column : s)
    for (const double v : column.second)
      finite = finite && std::isfinite(v);
  const std::vector<double> none;
  const auto               &time  = s.count("time") ? s.at("time") : none;
  const unsigned int        n     = time.size();
  double                    scale = 0, excess = 0;
  for (unsigned int i = 0; i < n; ++i)
    {
      scale =
        std::max(scale, s.at("kinetic_energy")[i] + s.at("elastic_energy")[i]);
      excess = std::max(excess, s.at("energy_balance_error")[i]);
    }
  const bool completed = error.empty();
  dealii::deallog << c.name << ": "
                  << (completed ? "completed" : "stopped with a message")
                  << std::endl;
  check_true(c.name + ": every number written is finite", finite);
  if (completed)
    {
      check_true(c.name + ": reached the end time",
                 std::abs(time.back() - c.end_time) < 1e-9);
      check_true(c.name + ": energy <= initial + external work + tolerance",
                 excess <= c.energy_tolerance * scale);
    }
  else
    {
      check_true(c.name + ": the message names " + c.expected_entry,
                 error.find(c.expected_entry) != std::string::npos);
      // a stop after the first step keeps what was computed
      if (c.expected_entry == "Minimum time step")
        check_true(c.name + ": the completed steps are on disk",
                   n >= 1 && error.find("statistics.csv") != std::string::npos);
    }
  std::ofstream out("outcomes.csv", std::ios::app);
  out << '"' << c.name << "\"," << (completed ? "completed" : "stopped") << ','
      << (n ? time.back() : 0.) << ',' << (n ? s.at("step").back() : 0.) << ','
      << (n ? s.at("time_step_cuts").back() : 0.) << ','
      << (scale > 0 ? excess / scale : 0.) << ",\"";
  auto start = error.find("The time step");
  if (start == std::string::npos)
    start = error.find("The bodies");
  if (start != std::string::npos)
    out << dealii::Utilities::trim(
      error.substr(start, error.find(". ", start) - start));
  out << "\"\n";
}

#endif
