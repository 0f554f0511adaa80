// A checkpoint written before an entry existed (here Finite
// element/Polynomial degree, added with issue 41) restarts under the new
// program: the missing entry counts with the value the old program had
// (degree 1), so only a real change of it is reported.
#include <contact_dynamics/output/checkpoint.h>

#include "tests.h"

int
main()
{
  initlog();
  const std::string old_text    = "subsection Time integration\n"
                                  "  set Time step = 0.01\n"
                                  "end\n";
  const auto        with_degree = [](const std::string &p) {
    return "subsection Finite element\n  set Polynomial degree = " + p +
           "\nend\nsubsection Time integration\n  set Time step = 0.01\n"
                  "end\n";
  };
  const auto same =
    ContactDynamics::Checkpoints::changed_entries(old_text,
                                                  with_degree("1"),
                                                  {});
  check_true("an old checkpoint without the entry, degree 1 now: no change",
             same.empty());
  const auto changed =
    ContactDynamics::Checkpoints::changed_entries(old_text,
                                                  with_degree("2"),
                                                  {});
  check_true("degree 2 now: reported as 'Finite element/Polynomial degree: "
             "1 -> 2'",
             changed.size() == 1 &&
               changed[0] == "Finite element/Polynomial degree: 1 -> 2");
  const auto other = ContactDynamics::Checkpoints::changed_entries(
    old_text,
    "subsection Time integration\n  set Time step = 0.02\nend\n",
    {});
  check_true("another entry that changed is still reported",
             other.size() == 1 &&
               other[0] == "Time integration/Time step: 0.01 -> 0.02");
}
