// Declarations of the deal.II classes the solver headers name, so that they
// need not include the Trilinos wrappers (compile time).
#ifndef contact_dynamics_solvers_trilinos_forward_h
#define contact_dynamics_solvers_trilinos_forward_h

#include <deal.II/base/config.h>

DEAL_II_NAMESPACE_OPEN
class DynamicSparsityPattern;
class ParameterHandler;
class SolverControl;
namespace TrilinosWrappers
{
  class SparseMatrix;
  class SolverDirect;
  class PreconditionBlockwiseDirect;
  class PreconditionAMG;
  namespace MPI
  {
    class Vector;
  }
} // namespace TrilinosWrappers
DEAL_II_NAMESPACE_CLOSE

#endif
