#include <contact_dynamics/application.h>

int
main(int argc, char **argv)
{
  return ContactDynamics::run_command_line(argc, argv);
}
