// The value of GLIBC_TUNABLES with which the program restarts itself
// (include/contact_dynamics/huge_pages.h), against what glibc's manual
// says of the variable: colon-separated name=value pairs, so a user's own
// tunables are kept and the new one appended; a user's own
// glibc.malloc.hugetlb (0, 1 or 2; the name compared whole) is left alone;
// nothing changes when switched off or when the kernel never
// gives huge pages; a setting other than 0 or 1 is refused with a message
// that names the variable and the value (cut at 40 characters). Whether a run
// then holds huge pages is reliability.huge_pages.
#include <contact_dynamics/huge_pages.h>

#include "tests.h"

#include <stdexcept>

using namespace dealii;
using namespace ContactDynamics::HugePages;

int
main()
{
  initlog();
  const auto show = [](const std::string &what, const std::string &value) {
    deallog << what << ": '" << value << "'" << std::endl;
  };
  show("unset", tunables(nullptr, nullptr, true));
  show("empty", tunables("", nullptr, true));
  show("user's other tunable kept",
       tunables("glibc.malloc.arena_max=2", "1", true));
  show("user's own choice", tunables("glibc.malloc.hugetlb=0", nullptr, true));
  show("user's own, among others",
       tunables("glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1",
                nullptr,
                true));
  show("a longer name is another tunable",
       tunables("xglibc.malloc.hugetlb=1", nullptr, true));
  show("trailing colon", tunables("glibc.malloc.arena_max=2:", nullptr, true));
  show("switched off", tunables(nullptr, "0", true));
  show("kernel never", tunables(nullptr, "1", false));
  for (const char *bad :
       {"", "2", "yes", "1 ", "1111111111222222222233333333334444444444x"})
    try
      {
        tunables(nullptr, bad, true);
        deallog << "'" << bad << "' accepted" << std::endl;
      }
    catch (const std::invalid_argument &e)
      {
        deallog << e.what() << std::endl;
      }
}
