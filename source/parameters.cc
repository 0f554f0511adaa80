#include <deal.II/base/utilities.h>

#include <contact_dynamics/parameters.h>

#include <iomanip>
#include <sstream>

namespace ContactDynamics
{
  std::string
  join(const std::vector<std::string> &parts, const std::string &separator)
  {
    std::string text;
    for (const auto &p : parts)
      text += (text.empty() ? "" : separator) + p;
    return text;
  }

  namespace
  {
    // "1e+06" -> "1e6", "1e-07" -> "1e-7"
    std::string
    without_exponent_padding(std::string text)
    {
      const std::size_t e = text.find('e');
      if (e == std::string::npos)
        return text;
      std::size_t digits = e + 1;
      if (text[digits] == '+')
        text.erase(digits, 1);
      else if (text[digits] == '-')
        ++digits;
      while (text[digits] == '0' && digits + 1 < text.size())
        text.erase(digits, 1);
      return text;
    }
  } // namespace

  std::string
  format_number(const double x)
  {
    std::ostringstream out;
    out << x;
    return out.str();
  }

  std::string
  default_text(const double x)
  {
    const std::string  text = without_exponent_padding(format_number(x));
    std::ostringstream scientific;
    scientific << std::scientific << std::setprecision(0) << x;
    // 1e4 rather than 10000, when it is exact and shorter
    const std::string short_form = without_exponent_padding(scientific.str());
    return (short_form.size() < text.size() &&
            Utilities::string_to_double(short_form) == x) ?
             short_form :
             text;
  }

  std::string
  default_text(const unsigned int n)
  {
    return std::to_string(n);
  }

  std::string
  default_text(const bool b)
  {
    return b ? "true" : "false";
  }
} // namespace ContactDynamics
