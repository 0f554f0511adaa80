#include <contact_dynamics/huge_pages.h>

#include <climits>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <sys/auxv.h>
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
      // set for the restarted program: it never restarts twice (glibc
      // drops tunables from setuid programs, which would loop otherwise)
      const char *restarted = "CONTACT_DYNAMICS_RESTARTED";

      bool
      first_process_of_run()
      {
        for (const char *rank : {"OMPI_COMM_WORLD_RANK", "PMI_RANK"})
          if (const char *r = std::getenv(rank))
            return std::string(r) == "0";
        return true;
      }
    } // namespace

    std::string
    tunables(const char *current, const char *setting, const bool kernel_offers)
    {
      const std::string value = setting == nullptr ? "1" : setting;
      if (value != "0" && value != "1")
        throw std::invalid_argument(
          "the environment variable CONTACT_DYNAMICS_HUGE_PAGES is '" +
          (value.size() > 40 ? value.substr(0, 40) + "..." : value) +
          "': it must be 1 (the heap in transparent huge pages where the "
          "kernel offers them, the default) or 0 (4 KB pages).");
      if (value == "0" || !kernel_offers)
        return "";
      const std::string present = current == nullptr ? "" : current;
      // the user's own setting of this tunable stands (names compared whole)
      std::istringstream pairs(present);
      for (std::string pair; std::getline(pairs, pair, ':');)
        if (pair.substr(0, pair.find('=')) == tunable)
          return "";
      return present + (present.empty() || present.back() == ':' ? "" : ":") +
             tunable + "=1";
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
      if (std::getenv(restarted) != nullptr)
        {
          unsetenv(restarted);
          return true;
        }
      std::string value;
      try
        {
          value = tunables(std::getenv("GLIBC_TUNABLES"),
                           std::getenv("CONTACT_DYNAMICS_HUGE_PAGES"),
                           kernel_offers());
        }
      catch (const std::invalid_argument &e)
        {
          if (first_process_of_run())
            std::cerr << "Error: " << e.what() << std::endl;
          return false;
        }
      // not for setuid programs (glibc ignores the tunable there) nor under
      // valgrind, which a restart would leave
      const char *preload = std::getenv("LD_PRELOAD");
      if (value.empty() || getauxval(AT_SECURE) != 0 ||
          (preload != nullptr &&
           std::string(preload).find("vgpreload") != std::string::npos))
        return true;
      setenv("GLIBC_TUNABLES", value.c_str(), 1);
      setenv(restarted, "1", 1);
      // the name it was started by (a link's name, for top and pgrep) if
      // that is this file (not the dynamic loader's)
      const std::string self = executable_path();
      const char       *started_as =
        reinterpret_cast<const char *>(getauxval(AT_EXECFN));
      char resolved[PATH_MAX];
      if (started_as == nullptr || realpath(started_as, resolved) == nullptr ||
          self != resolved)
        started_as = self.empty() ? "/proc/self/exe" : self.c_str();
      execv(started_as, argv);
      // not restarted: the run goes on with small pages
      unsetenv(restarted);
      return true;
    }
  } // namespace HugePages
} // namespace ContactDynamics
