// The bulk assembly with cached matrices (issue 16) against independent
// computations, on two bodies (the upper neo-Hookean, the lower linear
// elastic, both with inertia and Rayleigh damping; the lower one's bottom
// prescribed):
// 1. the Newton Jacobian against central differences of the residual, with
//    the Dirichlet rows and columns of the Jacobian eliminated;
// 2. the kinetic and elastic energies against quadrature with FEValues
//    (the computation the cached matrices replaced), and the kinetic energy
//    of a rigid translation against 1/2 m |v|^2;
// 3. one and two threads give the same residual and Jacobian, bit for bit;
// 4. an element inverted in a worker thread cuts the time step (the
//    exception reaches the Newton solver) instead of ending the run.
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <contact_dynamics/mechanics/material.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <random>

using namespace dealii;
using ContactDynamics::MatrixType;
using ContactDynamics::VectorType;

namespace
{
  std::string
  two_bodies(const std::string &upper_u,
             const std::string &upper_v,
             const std::string &lower_u,
             const std::string &lower_v)
  {
    return R"(
subsection Scene
  set Scene = two blocks
  subsection Two blocks
    set Gap = 0.1
  end
end
subsection Body upper
  set Material model = neo-Hookean
  set Young's modulus = 100
  set Poisson's ratio = 0.35
  set Density = 3
  set Rayleigh mass coefficient = 0.3
  set Rayleigh stiffness coefficient = 0.02
  set Body force = 1, -2
  set Initial displacement = )" +
           upper_u + R"(
  set Initial velocity = )" +
           upper_v + R"(
end
subsection Body lower
  set Material model = linear elastic
  set Young's modulus = 50
  set Poisson's ratio = 0.25
  set Density = 2
  set Rayleigh mass coefficient = 0.1
  set Rayleigh stiffness coefficient = 0.01
  set Initial displacement = )" +
           lower_u + R"(
  set Initial velocity = )" +
           lower_v + R"(
end
subsection Boundary conditions
  set Dirichlet = lower_bottom: x: t; lower_bottom: y: -2*t
end
subsection Output
  set Output directory = output_bulk
  set VTU interval = 0
end
)";
  }

  ContactDynamics::MaterialParameters
  material(const bool upper)
  {
    ContactDynamics::MaterialParameters p;
    p.model = ContactDynamics::MaterialParameters::model_named(
      upper ? "neo-Hookean" : "linear elastic");
    p.youngs_modulus = upper ? 100 : 50;
    p.poissons_ratio = upper ? 0.35 : 0.25;
    p.density        = upper ? 3 : 2;
    return p;
  }

  // kinetic and elastic energy by quadrature at every point
  std::pair<double, double>
  quadrature_energies(const ContactDynamics::Simulator<2> &simulator)
  {
    const auto &dof_handler = simulator.get_dof_handler();
    IndexSet    relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    VectorType u, v;
    u.reinit(dof_handler.locally_owned_dofs(), relevant, MPI_COMM_WORLD);
    v.reinit(u);
    u = simulator.displacement();
    v = simulator.velocity();
    const QGauss<2>                  quadrature(2);
    FEValues<2>                      fe_values(dof_handler.get_fe(),
                          quadrature,
                          update_values | update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, 2>>        grad_u(quadrature.size());
    std::vector<Tensor<1, 2>>        values(quadrature.size());
    double                           kinetic = 0, elastic = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[displacement].get_function_gradients(u, grad_u);
        fe_values[displacement].get_function_values(v, values);
        const auto p = material(cell->material_id() == 0);
        const auto m = ContactDynamics::create_material<2>(p);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            Tensor<2, 2> P;
            Tensor<4, 2> A;
            double       W;
            m->evaluate(grad_u[q], P, A, W);
            elastic += W * fe_values.JxW(q);
            kinetic +=
              0.5 * p.density * values[q] * values[q] * fe_values.JxW(q);
          }
      }
    return {kinetic, elastic};
  }

  void
  check_energies()
  {
    {
      ParameterHandler prm;
      read_test_parameters("translation.prm",
                           two_bodies("0; 0", "1; -2", "0; 0", "1; -2"),
                           prm);
      std::ostringstream            screen;
      ContactDynamics::Simulator<2> simulator(prm, screen);
      simulator.initialize();
      // masses 3 * 0.25 and 2 * 0.5, |v|^2 = 5
      check_close("kinetic energy of a translation = 1/2 m |v|^2",
                  simulator.energy().kinetic,
                  0.5 * 1.75 * 5,
                  1e-12);
    }
    ParameterHandler prm;
    read_test_parameters("fields.prm",
                         two_bodies("0.05*x*y; -0.08*x*x",
                                    "0.3*y; -0.2*x*x",
                                    "0.02*y*y; 0.01*x*y",
                                    "1 + 0.5*y*y; -2 + x*y"),
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    const auto [kinetic, elastic] = quadrature_energies(simulator);
    check_close("kinetic energy = quadrature",
                simulator.energy().kinetic / kinetic,
                1.,
                1e-12);
    check_close("elastic energy = quadrature",
                simulator.energy().elastic / elastic,
                1.,
                1e-12);
  }

  void
  check_jacobian()
  {
    ParameterHandler prm;
    read_test_parameters("jacobian.prm",
                         two_bodies("0.05*x*y; -0.08*x*x",
                                    "0.3*y; -0.2*x",
                                    "0.02*y*y; 0.01*x*y",
                                    "1; -2"),
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    const auto &constraints = simulator.get_constraints();

    VectorType trial(simulator.displacement()), direction(trial),
      residual(trial), residual_plus(trial), residual_minus(trial), jd(trial);
    std::mt19937                           rng(7);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (auto &x : trial)
      x += 0.02 * uniform(rng);
    for (auto &x : direction)
      x = uniform(rng);
    // Newton increments vanish at the prescribed dofs
    constraints.set_zero(direction);

    const double dt = 0.01, h = 1e-6;
    VectorType   shifted(trial);
    shifted.add(h, direction);
    simulator.residual_and_jacobian(shifted, dt, residual_plus);
    shifted.add(-2 * h, direction);
    simulator.residual_and_jacobian(shifted, dt, residual_minus);

    // one thread, then two (the machine may have one core only: then
    // both runs are sequential)
    MultithreadInfo::set_thread_limit(1);
    MatrixType one_thread;
    one_thread.copy_from(simulator.residual_and_jacobian(trial, dt, residual));
    const VectorType residual_one_thread(residual);
    MultithreadInfo::set_thread_limit(2);
    const auto &jacobian = simulator.residual_and_jacobian(trial, dt, residual);

    jacobian.vmult(jd, direction);
    VectorType fd(residual_plus);
    fd -= residual_minus;
    fd /= 2 * h;
    const double norm = jd.l2_norm();
    fd -= jd;
    check_close("|J d - finite differences| / |J d|",
                fd.l2_norm() / norm,
                0.,
                1e-7);
    record_measured("|J d - finite differences| / |J d|",
                    fd.l2_norm() / norm,
                    0.,
                    1e-7);

    // prescribed rows and columns: a positive diagonal entry only
    bool eliminated = true;
    for (unsigned int row = 0; row < jacobian.m(); ++row)
      for (auto entry = jacobian.begin(row); entry != jacobian.end(row);
           ++entry)
        if ((constraints.is_constrained(row) ||
             constraints.is_constrained(entry->column())) &&
            (entry->column() == row ? !(entry->value() > 0) :
                                      entry->value() != 0))
          eliminated = false;
    check_true("Dirichlet rows and columns eliminated, diagonal > 0",
               eliminated);

    VectorType difference(residual);
    difference -= residual_one_thread;
    one_thread.add(-1., jacobian);
    check_true("one and two threads: the same residual and Jacobian",
               difference.linfty_norm() == 0 &&
                 one_thread.frobenius_norm() == 0);
  }

  void
  check_inverted_element_cuts_the_step()
  {
    ParameterHandler prm;
    read_test_parameters("inverted.prm",
                         R"(
subsection Scene
  set Scene = block
  subsection Block
    set Size = 1, 1
    set Subdivisions = 2, 2
  end
end
subsection Body body
  set Material model = neo-Hookean
  set Young's modulus = 10
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  # the first trial state puts the right nodes left of the middle ones
  set Dirichlet = left: x: 0; bottom: y: 0; right: x: -0.6*t
end
subsection Time integration
  set Scheme = quasi-static
  set Time step = 1
  set End time = 1
  set Minimum time step = 0.1
end
subsection Output
  set Output directory = output_inverted
  set VTU interval = 0
end
)",
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    MultithreadInfo::set_thread_limit(2);
    simulator.run();
    const auto columns = read_csv_columns("output_inverted/statistics.csv");
    check_true("an inverted element is reported",
               screen.str().find("Inverted element") != std::string::npos);
    check_true("... and cuts the step",
               columns.at("time_step_cuts").back() > 0);
    check_close("final time", simulator.current_time(), 1., 1e-12);
  }
} // namespace

int
main()
{
  initlog();
  check_jacobian();
  check_energies();
  check_inverted_element_cuts_the_step();
}
