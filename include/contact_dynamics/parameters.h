// Helpers that let a class declare each parameter default exactly once: in
// the initializer of the member that holds the parsed value. The static
// declare_parameters() of the class reads the defaults from a
// default-constructed object and writes them with default_text(); a
// selection is parsed into an enum through one name table.
#ifndef contact_dynamics_parameters_h
#define contact_dynamics_parameters_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/patterns.h>

#include <initializer_list>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  /** The parts with `separator` between them (for messages). */
  std::string
  join(const std::vector<std::string> &parts,
       const std::string              &separator = ", ");

  /** x with 6 significant digits, as an ostream writes it (1e-07). */
  std::string
  format_number(const double x);

  /**
   * While alive, std::cerr writes into a buffer that is dropped: deal.II's
   * FunctionParser dumps muparser's error there before it throws, and the
   * caller's message says it in the parameter's terms.
   */
  class SilencedStdErr
  {
  public:
    SilencedStdErr()
      : buffer(std::cerr.rdbuf(dump.rdbuf()))
    {}
    ~SilencedStdErr()
    {
      std::cerr.rdbuf(buffer);
    }
    SilencedStdErr(const SilencedStdErr &) = delete;
    SilencedStdErr &
    operator=(const SilencedStdErr &) = delete;

  private:
    std::ostringstream dump;
    std::streambuf    *buffer;
  };

  /**
   * The text of a default in the parameter file: format_number() without
   * '+' and leading zeros in the exponent (1e6, 1e-10), as people write it.
   */
  std::string
  default_text(const double x);

  std::string
  default_text(const unsigned int n);

  std::string
  default_text(const bool b);

  /**
   * The names of an enum's values in a parameter file: the pattern of the
   * entry, the name of a value (for its default) and the value of a name.
   */
  template <typename Enum>
  class Selection
  {
  public:
    Selection(std::initializer_list<std::pair<Enum, std::string>> names)
      : names(names)
    {}

    /** "a|b|c", in the order of the table. */
    Patterns::Selection
    pattern() const
    {
      return Patterns::Selection(joined("|"));
    }

    const std::string &
    name(const Enum value) const
    {
      for (const auto &n : names)
        if (n.first == value)
          return n.second;
      AssertThrow(false, ExcInternalError());
      return names.front().second;
    }

    Enum
    value(const std::string &name) const
    {
      for (const auto &n : names)
        if (n.second == name)
          return n.first;
      AssertThrow(false,
                  ExcMessage("Unknown value '" + name +
                             "'; allowed: " + joined(", ") + "."));
      return names.front().first;
    }

  private:
    std::string
    joined(const std::string &separator) const
    {
      std::string text;
      for (const auto &n : names)
        text += (text.empty() ? "" : separator) + n.second;
      return text;
    }


    std::vector<std::pair<Enum, std::string>> names;
  };
} // namespace ContactDynamics

#endif
