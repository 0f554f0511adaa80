#include <deal.II/base/utilities.h>

#include <contact_dynamics/contact/contact_formulation.h>
#include <contact_dynamics/output/contact_writer.h>
#include <contact_dynamics/output/postprocessing.h>
#include <contact_dynamics/parallel.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace ContactDynamics
{
  template <int dim>
  ContactWriter<dim>::ContactWriter(const ContactFormulation<dim> &contact,
                                    const MPI_Comm                 comm,
                                    const std::string             &directory,
                                    const bool                     append)
    : comm(comm)
    , directory(directory)
  {
    locate_monitored_nodes(contact);
    if (directory.empty() || !is_root(comm))
      return;
    errno = 0;
    history =
      std::make_unique<std::ofstream>(history_name(),
                                      append ? std::ios::app : std::ios::out);
    check_written(*history, history_name());
    if (append)
      return;
    *history << "time";
    for (const auto &m : monitored)
      {
        const auto &X = contact.secondary_nodes(m.first).reference[m.second];
        std::ostringstream where;
        for (unsigned int k = 0; k < dim; ++k)
          where << (k ? " " : "") << X[k];
        *history << ",pressure(" << where.str() << ")"
                 << ",gap(" << where.str() << ")";
      }
    *history << std::endl;
    check_written(*history, history_name());
  }

  template <int dim>
  void
  ContactWriter<dim>::locate_monitored_nodes(
    const ContactFormulation<dim> &contact)
  {
    // monitored points: the nearest secondary node of any pair
    monitored.clear();
    for (const auto &point : contact.monitored_points())
      {
        double                                best = 1e300;
        std::pair<unsigned int, unsigned int> where{0, 0};
        for (unsigned int p = 0; p < contact.n_pairs(); ++p)
          {
            const auto &reference = contact.secondary_nodes(p).reference;
            for (unsigned int j = 0; j < reference.size(); ++j)
              {
                double d = 0;
                for (unsigned int k = 0; k < dim; ++k)
                  d += std::pow(reference[j][k] - point[k], 2);
                if (d < best)
                  {
                    best  = d;
                    where = {p, j};
                  }
              }
          }
        monitored.push_back(where);
      }
  }

  template <int dim>
  std::string
  ContactWriter<dim>::history_name() const
  {
    return directory + "/contact_history.csv";
  }

  template <int dim>
  void
  ContactWriter<dim>::write_history(const ContactFormulation<dim> &contact,
                                    const double                   time)
  {
    if (!history)
      return;
    *history << std::setprecision(10) << time;
    for (const auto &m : monitored)
      {
        const auto &node = contact.secondary_nodes(m.first).states[m.second];
        *history << ',' << node.pressure << ',' << node.normalized_gap();
      }
    errno = 0;
    *history << std::endl;
    check_written(*history, history_name());
  }

  template <int dim>
  void
  ContactWriter<dim>::write_surfaces(const ContactFormulation<dim> &contact,
                                     const unsigned int             step) const
  {
    if (!is_root(comm))
      return;
    write_file_atomically(directory + "/contact_surface-" +
                            Utilities::int_to_string(step, 5) + ".csv",
                          [&](std::ostream &out) {
                            write_surfaces(contact, out);
                          });
  }

  template <int dim>
  void
  ContactWriter<dim>::write_surfaces(const ContactFormulation<dim> &contact,
                                     std::ostream                  &out) const
  {
    out << "pair,node,x,y," << (dim == 3 ? "z," : "")
        << "gap,pressure,active,tangential_traction,"
        << (dim == 3 ? "tangential_traction_2," : "") << "stick,slip_rate"
        << (dim == 3 ? ",slip_rate_2" : "");
    // then the columns of the owners of node history (the same per pair)
    if (contact.n_pairs() > 0)
      for (const auto &column : contact.secondary_nodes(0).columns)
        out << ',' << column.name;
    out << '\n';
    for (unsigned int p = 0; p < contact.n_pairs(); ++p)
      {
        const SecondaryNodes<dim> nodes = contact.secondary_nodes(p);
        const auto               &X     = nodes.reference;
        // along the surface for straight ones: by reference x, then y
        std::vector<unsigned int> order(X.size());
        for (unsigned int j = 0; j < order.size(); ++j)
          order[j] = j;
        std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) {
          for (unsigned int d = 0; d < dim; ++d)
            if (X[a][d] != X[b][d])
              return X[a][d] < X[b][d];
          return false;
        });
        for (const unsigned int j : order)
          {
            const ContactNodeState &node = nodes.states[j];
            const auto             &x    = nodes.position[j];
            out << p << ',' << j << ',' << std::setprecision(10);
            for (unsigned int d = 0; d < dim; ++d)
              out << x[d] << ',';
            out << node.normalized_gap() << ',' << node.pressure << ','
                << node.active << ',';
            for (unsigned int a = 0; a + 1 < dim; ++a)
              out << node.tangential[a] << ',';
            out << node.stick;
            for (unsigned int a = 0; a + 1 < dim; ++a)
              out << ',' << node.slip_rate[a];
            for (const auto &column : nodes.columns)
              out << ',' << column.values[j];
            out << '\n';
          }
      }
  }

  template class ContactWriter<2>;
  template class ContactWriter<3>;
} // namespace ContactDynamics
