// The contact CSV files: contact_history.csv (the secondary nodes nearest
// to the monitored points, one row per step) and contact_surface-NNNNN.csv
// (every secondary node at an output step). The first process writes them
// from the node states the contact formulation makes known everywhere.
#ifndef contact_dynamics_output_contact_writer_h
#define contact_dynamics_output_contact_writer_h

#include <deal.II/base/mpi.h>

#include <fstream>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace ContactDynamics
{
  template <int dim>
  class ContactFormulation;

  template <int dim>
  class ContactWriter
  {
  public:
    /**
     * After the contact's setup(): finds the secondary node nearest to each
     * monitored point and starts contact_history.csv (unless `directory` is
     * empty); `append`: a restarted run continues it.
     */
    ContactWriter(const ContactFormulation<dim> &contact,
                  const MPI_Comm                 comm,
                  const std::string             &directory,
                  const bool                     append = false);

    /**
     * The secondary node nearest to each monitored point (again after a
     * mesh change: a refined mesh may have a nearer one).
     */
    void
    locate_monitored_nodes(const ContactFormulation<dim> &contact);

    /** A row of contact_history.csv after the step to `time`; every write
     * is checked (throws naming the file). */
    void
    write_history(const ContactFormulation<dim> &contact, const double time);

    /** contact_surface-NNNNN.csv at output step `step` (written under a
     * temporary name, then renamed). */
    void
    write_surfaces(const ContactFormulation<dim> &contact,
                   const unsigned int             step) const;

  private:
    void
    write_surfaces(const ContactFormulation<dim> &contact,
                   std::ostream                  &out) const;
    std::string
    history_name() const;

    MPI_Comm                                           comm;
    std::string                                        directory;
    std::vector<std::pair<unsigned int, unsigned int>> monitored; // pair, node
    std::unique_ptr<std::ofstream>                     history;
  };
} // namespace ContactDynamics

#endif
