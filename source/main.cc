#include <contact_dynamics/huge_pages.h>

#include <dlfcn.h>
#include <iostream>
#include <string>

// A thin start: the program may start itself again with the heap in huge
// pages (huge_pages.h), so the library, whose loading is about 0.4 s of
// every run (about 300 shared libraries), is opened only after that.
int
main(int argc, char **argv)
{
  if (!ContactDynamics::HugePages::restart_with_huge_pages(argv))
    return 1;
  const char *name = "libcontact-dynamics-lib.so";
  // LD_LIBRARY_PATH first (benchmarks/paired_builds.py swaps the library
  // that way), then the executable's own directory (its RUNPATH is
  // $ORIGIN), then the system's
  void *library = dlopen(name, RTLD_NOW | RTLD_GLOBAL);
  if (library == nullptr)
    {
      std::cerr << "Error: cannot open " << name << " (searched in "
                << "LD_LIBRARY_PATH, then next to the executable "
                << ContactDynamics::executable_path()
                << ", then the system's directories): " << dlerror()
                << std::endl;
      return 1;
    }
  using Entry    = int (*)(int, char **);
  const auto run = reinterpret_cast<Entry>(
    dlsym(library, "contact_dynamics_run_command_line"));
  if (run == nullptr)
    {
      std::cerr << "Error: " << name << " has no entry point: " << dlerror()
                << std::endl;
      return 1;
    }
  return run(argc, argv);
}
