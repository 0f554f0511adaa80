// Shared helpers for the .cc unit tests: deallog goes to the file "output"
// that the deal.II test harness compares with the .output file.
#ifndef contact_dynamics_tests_h
#define contact_dynamics_tests_h

#include <deal.II/base/logstream.h>

#include <fstream>
#include <iomanip>

inline std::ofstream &
initlog()
{
  static std::ofstream logfile("output");
  dealii::deallog.attach(logfile);
  dealii::deallog.depth_console(0);
  logfile << std::setprecision(6);
  return logfile;
}

// Prints "name: OK" if |value - expected| <= tolerance, and the numbers
// otherwise, so that a failure shows up as a diff.
inline void
check_close(const std::string &name,
            const double       value,
            const double       expected,
            const double       tolerance)
{
  if (std::abs(value - expected) <= tolerance)
    dealii::deallog << name << ": OK" << std::endl;
  else
    dealii::deallog << name << ": FAILED value=" << std::setprecision(12)
                    << value << " expected=" << expected
                    << " tolerance=" << tolerance << std::endl;
}

inline void
check_true(const std::string &name, const bool condition)
{
  dealii::deallog << name << ": " << (condition ? "OK" : "FAILED")
                  << std::endl;
}

#endif
