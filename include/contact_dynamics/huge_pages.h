#ifndef contact_dynamics_huge_pages_h
#define contact_dynamics_huge_pages_h

#include <string>

namespace ContactDynamics
{
  /** The running program's file (empty if /proc cannot tell). */
  std::string
  executable_path();

  /**
   * Transparent huge pages for the heap (doc/parallel.md, "Memory pages").
   *
   * A run touches most of its memory once (matrices, multigrid levels), and
   * with 4 KB pages every first touch is a page fault: 186,000 of them at
   * 298k unknowns. glibc's malloc asks the kernel for 2 MB pages when the
   * tunable glibc.malloc.hugetlb=1 is set, but tunables are read when the
   * process starts, so the program starts itself again with it.
   */
  namespace HugePages
  {
    /**
     * The value GLIBC_TUNABLES should get, from its present value
     * (`current`, nullptr if unset), the setting of
     * CONTACT_DYNAMICS_HUGE_PAGES (`setting`, nullptr if unset: on) and
     * whether the kernel offers huge pages to a process that asks
     * (`kernel_offers`). Empty if nothing is to change: switched off, the
     * kernel never gives them, or GLIBC_TUNABLES already says what malloc
     * does with huge pages. Throws std::invalid_argument with a message if
     * `setting` is neither 0 nor 1.
     */
    std::string
    tunables(const char *current, const char *setting, bool kernel_offers);

    /**
     * True unless /sys/kernel/mm/transparent_hugepage/enabled says never
     * (or cannot be read).
     */
    bool
    kernel_offers();

    /**
     * Starts this program again with the tunable if tunables() asks for it;
     * returns if it does not (or the restart fails: then the run goes on
     * with 4 KB pages). False, with a message on standard error, if
     * CONTACT_DYNAMICS_HUGE_PAGES has a value that is not allowed.
     */
    bool
    restart_with_huge_pages(char **argv);
  } // namespace HugePages
} // namespace ContactDynamics

#endif
