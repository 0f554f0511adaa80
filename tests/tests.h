// Shared helpers for the .cc unit tests: deallog goes to the file "output"
// that the deal.II test harness compares with the .output file.
#ifndef contact_dynamics_tests_h
#define contact_dynamics_tests_h

#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector_memory.h>

#include <fstream>
#include <iomanip>

inline std::ofstream &
initlog()
{
  // the library uses MPI (Trilinos), also in serial
  static int    argc   = 1;
  static char   name[] = "test";
  static char  *args[] = {name, nullptr};
  static char **argv   = args;
  // deal.II's pool of Trilinos vectors (a function-local static that every
  // deal.II solver on them touches) made before `mpi`, so that it still
  // exists when ~MPI_InitFinalize releases it
  static const bool pool = [] {
    dealii::GrowingVectorMemory<dealii::TrilinosWrappers::MPI::Vector> touch;
    return true;
  }();
  (void)pool;
  static dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // under mpirun the first process writes the output
  static std::ofstream logfile(
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ?
      "output" :
      "/dev/null");
  dealii::deallog.attach(logfile);
  dealii::deallog.depth_console(0);
  logfile << std::setprecision(6);
  return logfile;
}

// Prints "name: OK" if |value - expected| <= tolerance, and the numbers
// otherwise, so that a failure shows up as a diff.
inline void
check_close(const std::string &name,
            const double       value,
            const double       expected,
            const double       tolerance)
{
  if (std::abs(value - expected) <= tolerance)
    dealii::deallog << name << ": OK" << std::endl;
  else
    dealii::deallog << name << ": FAILED value=" << std::setprecision(12)
                    << value << " expected=" << expected
                    << " tolerance=" << tolerance << std::endl;
}

inline void
check_true(const std::string &name, const bool condition)
{
  dealii::deallog << name << ": " << (condition ? "OK" : "FAILED") << std::endl;
}


// A measured value beside the checks: appended to the file "measured" next
// to "output" (the harness does not compare it), so that the margin of
// every tolerance can be read after a run (doc/testing.md quotes them).
inline void
record_measured(const std::string &name,
                const double       value,
                const double       low,
                const double       high)
{
  static std::ofstream file(
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ?
      "measured" :
      "/dev/null");
  file << std::setprecision(6) << name << ": " << value << " in [" << low
       << ", " << high << "]" << std::endl;
}

// Prints "name: OK" if low <= value <= high, and the numbers otherwise;
// the value is recorded in the file "measured" either way.
inline void
check_range(const std::string &name,
            const double       value,
            const double       low,
            const double       high)
{
  record_measured(name, value, low, high);
  if (value >= low && value <= high)
    dealii::deallog << name << ": OK" << std::endl;
  else
    dealii::deallog << name << ": FAILED value=" << std::setprecision(12)
                    << value << " range=[" << low << ", " << high << "]"
                    << std::endl;
}


#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/application.h>
#include <contact_dynamics/contact/contact_formulation.h>
#include <contact_dynamics/scenes/scene.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

// Mean velocity component (momentum / mass) of the 2-D Q1 body with
// material id `body`, with row-sum (lumped) nodal masses, which give the
// momentum exactly (uniform density and parallelogram cells).
template <typename Simulator>
double
mean_velocity(const Simulator   &simulator,
              const unsigned int body,
              const unsigned int component)
{
  double momentum = 0, mass = 0;
  for (const auto &cell : simulator.get_dof_handler().active_cell_iterators())
    if (cell->material_id() == body)
      for (unsigned int v = 0; v < 4; ++v)
        {
          momentum +=
            cell->measure() / 4 *
            simulator.velocity()(cell->vertex_dof_index(v, component));
          mass += cell->measure() / 4;
        }
  return momentum / mass;
}

template <typename Simulator>
double
mean_velocity_x(const Simulator &simulator, const unsigned int body)
{
  return mean_velocity(simulator, body, 0);
}

// Active, active and held (persistent), and sticking nodes among `states`.
template <typename States>
std::array<unsigned int, 3>
count_node_states(const States &states)
{
  std::array<unsigned int, 3> n = {{0, 0, 0}};
  for (const auto &node : states)
    {
      n[0] += node.active;
      n[1] += node.active && node.persistent;
      n[2] += node.stick;
    }
  return n;
}

// Nodes of a contact surface whose displacement hangs (follows other nodes)
// under `constraints` (the simulator's: they hold those of every surface
// node on every process).
template <typename Surface, typename Constraints>
unsigned int
hanging_surface_nodes(const Surface &surface, const Constraints &constraints)
{
  unsigned int n = 0;
  for (const auto &node_dofs : surface.dofs)
    {
      const auto *entries = constraints.get_constraint_entries(node_dofs[0]);
      n += entries != nullptr && !entries->empty();
    }
  return n;
}

// The columns of a CSV file (a header line of names, then numbers) by name:
// statistics.csv and contact_history.csv are read only through this, so
// that no test depends on the order of the columns.
inline std::map<std::string, std::vector<double>>
read_csv_columns(const std::string &filename)
{
  std::ifstream in(filename);
  std::string   line;
  std::getline(in, line);
  const auto names = dealii::Utilities::split_string_list(line, ',');
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line))
    {
      const auto values = dealii::Utilities::split_string_list(line, ',');
      for (unsigned int i = 0; i < names.size() && i < values.size(); ++i)
        columns[names[i]].push_back(std::stod(values[i]));
    }
  return columns;
}

// The contact columns of the statistics.csv row of the current step by name
// (statistics_columns() names the values of statistics()).
template <int dim>
std::map<std::string, double>
contact_statistics(const ContactDynamics::ContactFormulation<dim> &contact)
{
  const auto names  = contact.statistics_columns();
  const auto values = contact.statistics();
  AssertThrow(names.size() == values.size(),
              dealii::ExcDimensionMismatch(names.size(), values.size()));
  std::map<std::string, double> row;
  for (unsigned int i = 0; i < names.size(); ++i)
    row[names[i]] = values[i];
  return row;
}

// A scene selected by name with its refinement factor; `extra` sets more
// entries inside subsection Scene.
template <int dim>
ContactDynamics::Scene<dim>
make_scene(const std::string                                     &name,
           const double                                           factor = 1,
           const std::function<void(dealii::ParameterHandler &)> &extra  = {})
{
  dealii::ParameterHandler prm;
  ContactDynamics::Scene<dim>::declare_parameters(prm);
  prm.enter_subsection("Scene");
  prm.set("Scene", name);
  prm.set("Refinement factor", factor);
  if (extra)
    extra(prm);
  prm.leave_subsection();
  ContactDynamics::Scene<dim> scene;
  scene.parse_parameters(prm);
  return scene;
}

// Writes `text` to `filename` and reads it as the application would.
inline void
read_test_parameters(const std::string        &filename,
                     const std::string        &text,
                     dealii::ParameterHandler &prm)
{
  // under mpirun: one process writes, all read once it is complete
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::ofstream f(filename);
      f << text;
    }
  MPI_Barrier(MPI_COMM_WORLD);
  ContactDynamics::read_parameters(filename, prm);
}

// The one-element axial mode of newmark_period.cc and
// generalized_alpha_period.cc: a Q1 element [0,2]x[0,0.5], E = 200, nu = 0,
// rho = 3, clamped on its left side and sliding on its right side, u_x =
// 0.001 x at t = 0 (one free mode, omega^2 = 3 E / (rho L^2)), the entries
// `time_integration` in its subsection, read into `prm`.
namespace AxialMode
{
  constexpr double E = 200, rho = 3, L = 2;
  // the mode's angular frequency and the step of 20 per period
  inline double
  omega()
  {
    return std::sqrt(3 * E / (rho * L * L));
  }
  inline double
  dt()
  {
    return 2 * M_PI / omega() / 20;
  }
} // namespace AxialMode

inline void
read_axial_mode_parameters(const std::string        &time_integration,
                           dealii::ParameterHandler &prm)
{
  read_test_parameters("axial_mode.prm",
                       R"(
subsection Scene
  set Scene = block
  subsection Block
    set Size = 2, 0.5
    set Subdivisions = 1, 1
  end
end
subsection Body body
  set Young's modulus = 200
  set Poisson's ratio = 0
  set Density = 3
  set Initial displacement = 0.001*x; 0
end
subsection Boundary conditions
  set Dirichlet = left: xy: 0; right: y: 0
end
subsection Time integration
)" + time_integration + R"(
end
subsection Output
  set Output directory = output_axial_mode
  set VTU interval = 0
end
)",
                       prm);
}

// The degree of freedom of `component` at the vertex at `point` (of a Q1
// mesh); throws if no vertex is there.
template <typename DoFHandlerType, typename PointType>
dealii::types::global_dof_index
vertex_dof(const DoFHandlerType &dof_handler,
           const PointType      &point,
           const unsigned int    component)
{
  for (const auto &cell : dof_handler.active_cell_iterators())
    for (const auto v : cell->vertex_indices())
      if (cell->vertex(v).distance(point) < 1e-12)
        return cell->vertex_dof_index(v, component);
  AssertThrow(false, dealii::ExcMessage("vertex_dof(): no vertex there"));
  return 0;
}

using ParameterChanges = std::vector<std::pair<std::string, std::string>>;

// Reads a shipped parameter file (path relative to the repository) with
// some entries replaced ({"Section/Entry", value}) into `prm`; returns the
// output directory if it is among the changes.
inline std::string
read_shipped(const std::string        &file,
             const ParameterChanges   &changes,
             dealii::ParameterHandler &prm)
{
  ContactDynamics::read_parameters(std::string(SOURCE_DIR) + "/../" + file,
                                   prm);
  std::string directory;
  for (const auto &change : changes)
    {
      const auto sections =
        dealii::Utilities::split_string_list(change.first, '/');
      for (unsigned int i = 0; i + 1 < sections.size(); ++i)
        prm.enter_subsection(sections[i]);
      prm.set(sections.back(), change.second);
      for (unsigned int i = 0; i + 1 < sections.size(); ++i)
        prm.leave_subsection();
      if (sections.back() == "Output directory")
        directory = change.second;
    }
  return directory;
}

// Runs a shipped parameter file with some entries replaced (read_shipped)
// and returns the columns of its statistics.csv by name.
// `inspect` sees the simulator at the end of the run. With `error`, a run
// that stops with an exception returns what it wrote, and the message. On
// several processes only the first one gets the columns.
template <typename Simulator>
std::map<std::string, std::vector<double>>
run_shipped(const std::string                            &file,
            const ParameterChanges                       &changes,
            const std::function<void(const Simulator &)> &inspect = {},
            std::string                                  *error   = nullptr,
            const MPI_Comm                                comm = MPI_COMM_WORLD)
{
  dealii::ParameterHandler prm;
  const std::string        directory = read_shipped(file, changes, prm);
  AssertThrow(!directory.empty(),
              dealii::ExcMessage("set Output/Output directory"));
  try
    {
      std::ostringstream screen;
      Simulator          simulator(prm, screen, comm);
      simulator.run();
      if (inspect)
        inspect(simulator);
    }
  catch (const std::exception &e)
    {
      if (!error)
        throw;
      *error = e.what();
    }

  if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
    return {};
  return read_csv_columns(directory + "/statistics.csv");
}

// Time of the first row where column `name` is positive, or -1.
inline double
first_time_positive(const std::map<std::string, std::vector<double>> &columns,
                    const std::string                                &name)
{
  const auto &values = columns.at(name);
  for (unsigned int i = 0; i < values.size(); ++i)
    if (values[i] > 0)
      return columns.at("time")[i];
  return -1;
}


// The Jacobian of a simulator's Newton system at `trial` (time step dt)
// against central differences of its residual (step h along `direction`):
// |J d - FD| / |J d| on the multiplier rows (`lambda`) and on the force
// rows (the other rows J reaches from `mask`, which is non-zero on the
// multipliers only) separately, so that the bulk rows cannot hide an
// error in the contact rows. `residual` receives the residual at trial.
struct ContactRowErrors
{
  double       multiplier_rows = 0, force_rows = 0;
  unsigned int n_multiplier_rows = 0, n_force_rows = 0;
};

template <typename Simulator, typename Vector>
ContactRowErrors
contact_row_errors(Simulator                                       &simulator,
                   const Vector                                    &trial,
                   const Vector                                    &direction,
                   const Vector                                    &mask,
                   const std::set<dealii::types::global_dof_index> &lambda,
                   const double                                     h,
                   const double                                     dt,
                   Vector                                          &residual)
{
  Vector r_plus(trial), r_minus(trial), jd(trial), jm(trial);
  Vector shifted(trial);
  shifted.add(h, direction);
  simulator.residual_and_jacobian(shifted, dt, r_plus);
  shifted.add(-2 * h, direction);
  simulator.residual_and_jacobian(shifted, dt, r_minus);
  const auto &J = simulator.residual_and_jacobian(trial, dt, residual);
  J.vmult(jd, direction);
  J.vmult(jm, mask);
  r_plus -= r_minus;
  r_plus /= 2 * h;
  const auto  &constraints = simulator.get_constraints();
  double       error[2] = {0, 0}, norm[2] = {0, 0};
  unsigned int n_rows[2] = {0, 0};
  for (unsigned int i = 0; i < trial.size(); ++i)
    {
      const int group = lambda.count(i) ? 0 : (jm(i) != 0 ? 1 : -1);
      if (group < 0 || constraints.is_constrained(i))
        continue;
      ++n_rows[group];
      error[group] += std::pow(r_plus(i) - jd(i), 2);
      norm[group] += std::pow(jd(i), 2);
    }
  return {std::sqrt(error[0] / norm[0]),
          std::sqrt(error[1] / norm[1]),
          n_rows[0],
          n_rows[1]};
}

#endif
