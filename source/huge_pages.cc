#include <contact_dynamics/huge_pages.h>

#include <climits>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <unistd.h>

namespace ContactDynamics
{
  std::string
  executable_path()
  {
    char       path[PATH_MAX];
    const auto n = readlink("/proc/self/exe", path, sizeof(path) - 1);
    return n > 0 ? std::string(path, n) : std::string();
  }

  namespace HugePages
  {
    namespace
    {
      const std::string tunable = "glibc.malloc.hugetlb";
    }

    std::string
    tunables(const char *current, const char *setting, const bool kernel_offers)
    {
      const std::string value = setting == nullptr ? "1" : setting;
      if (value != "0" && value != "1")
        throw std::invalid_argument(
          "the environment variable CONTACT_DYNAMICS_HUGE_PAGES is '" + value +
          "': it must be 1 (the heap in transparent huge pages where the "
          "kernel offers them, the default) or 0 (4 KB pages).");
      if (value == "0" || !kernel_offers)
        return "";
      const std::string present = current == nullptr ? "" : current;
      // the user's own choice stands (and the restarted program stops here)
      if (present.find(tunable + "=") != std::string::npos)
        return "";
      return (present.empty() ? "" : present + ":") + tunable + "=1";
    }

    bool
    kernel_offers()
    {
      std::ifstream file("/sys/kernel/mm/transparent_hugepage/enabled");
      std::string   modes;
      if (!std::getline(file, modes))
        return false;
      return modes.find("[never]") == std::string::npos;
    }

    bool
    restart_with_huge_pages(char **argv)
    {
      std::string value;
      try
        {
          value = tunables(std::getenv("GLIBC_TUNABLES"),
                           std::getenv("CONTACT_DYNAMICS_HUGE_PAGES"),
                           kernel_offers());
        }
      catch (const std::invalid_argument &e)
        {
          std::cerr << "Error: " << e.what() << std::endl;
          return false;
        }
      if (value.empty())
        return true;
      setenv("GLIBC_TUNABLES", value.c_str(), 1);
      // the file itself, not /proc/self/exe, so that the process keeps its
      // name (top, pgrep)
      const std::string self = executable_path();
      execv(self.empty() ? "/proc/self/exe" : self.c_str(), argv);
      // not restarted (no /proc?): the run goes on with small pages
      return true;
    }
  } // namespace HugePages
} // namespace ContactDynamics
