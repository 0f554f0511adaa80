// The command line: run a parameter file, check it, or print the defaults.
#ifndef contact_dynamics_application_h
#define contact_dynamics_application_h

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>

namespace ContactDynamics
{
  using namespace dealii;

  /**
   * Declares and reads every parameter of `filename` (two passes: the scene
   * decides which body subsections exist). Throws with a message naming the
   * file, line, entry and allowed values on bad input. Returns the
   * dimension.
   */
  unsigned int
  read_parameters(const std::string &filename, ParameterHandler &prm);

  /**
   * Runs the simulation described by `filename`, screen output to `screen`.
   * With `validate_only`, stops after reading and checking everything.
   * With `restart` (an output directory or a checkpoint), continues from
   * its newest checkpoint; an empty `filename` then takes the parameters
   * stored with it.
   */
  void
  run_parameter_file(const std::string &filename,
                     std::ostream      &screen,
                     const bool         validate_only = false,
                     const std::string &restart       = "");

  /** The command line of the contact-dynamics executable; returns the exit
   * status. */
  int
  run_command_line(int argc, char **argv);
} // namespace ContactDynamics

#endif
