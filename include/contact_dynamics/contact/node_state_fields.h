// The fields of a contact node's state as doubles, in one table: the
// checkpoints save them in this order, and the output fields are gathered
// from the processes that own the nodes with the same table.
#ifndef contact_dynamics_contact_node_state_fields_h
#define contact_dynamics_contact_node_state_fields_h

#include <contact_dynamics/contact/contact_formulation.h>

#include <vector>

namespace ContactDynamics
{
  /** One field of a ContactNodeState as a double (a bool as 0 or 1). */
  struct NodeStateField
  {
    const char *name;
    double (*get)(const ContactNodeState &);
    void (*set)(ContactNodeState &, const double);
  };

  /**
   * Every field in the order of a node's entries in a checkpoint
   * ("contact/pair p/nodes": 18 doubles per node). The last slot is
   * reserved: written as 0 and ignored on load since the first checkpoint
   * format, it keeps the checkpoints written since loadable.
   */
  const std::vector<NodeStateField> &
  node_state_fields();

  /**
   * The first fields of the table: what the output shows of a node, made
   * known on every process after each assembly.
   */
  constexpr unsigned int n_output_node_fields = 10;
} // namespace ContactDynamics

#endif
