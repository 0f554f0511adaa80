#include <contact_dynamics/parameters.h>

#include <sstream>

namespace ContactDynamics
{
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
    std::string       text = format_number(x);
    const std::size_t e    = text.find('e');
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
