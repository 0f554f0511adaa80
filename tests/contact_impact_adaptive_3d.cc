// A 3-D impact on a mesh that follows the contact: the bouncing block's
// block (linear elastic, no damping, nothing held) falls at 1 m/s onto the
// substrate, bounces and leaves; dual mortar with the velocity update
// (which keeps the energy of a contact exactly), each step solved again on
// the mesh adapted to its contact: one level near the contact zone,
// coarsened after the block left. The substrate's refined patch under the
// block has hanging nodes on the primary surface (the block's bottom, the
// secondary one, is refined whole; contact_patch_test_refined_3d has them
// on both). What follows from the physics, not from the code:
// - the energy E0 = (1/2) m v0^2 is conserved through the impact: at the
//   end E = E0 + transfer_energy to 1e-9 (the coarsening's velocity
//   projection loses some kinetic energy, never gains: between 0 and 3 %),
//   and the contact does no work (1e-9 of E0);
// - the block left: no active node at the end, after an impact that had
//   some, with hanging nodes on the primary surface during it;
// - the mesh came back to the initial one.
// On two processes (.mpirun=2) the same numbers.
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

using namespace dealii;

int
main()
{
  initlog();
  ParameterHandler prm;
  read_test_parameters("impact_3d.prm",
                       R"(
set Dimension = 3
subsection Scene
  set Scene             = bouncing block
  set Refinement factor = 0.3
  subsection Bouncing block
    set Depth elements = 3
  end
end
subsection Body block
  set Young's modulus      = 1e6
  set Poisson's ratio      = 0.3
  set Density              = 7750
  set Initial displacement = 0; 0.01; 0
  set Initial velocity     = 0; -1; 0
end
subsection Body substrate
  set Young's modulus = 1e8
  set Poisson's ratio = 0.3
  set Density         = 7750
end
subsection Boundary conditions
  set Dirichlet = substrate_bottom: xyz: 0
end
subsection Time integration
  set Time step = 0.01
  set End time  = 0.3
end
subsection Nonlinear solver
  set Absolute tolerance = 1e-9
end
subsection Contact
  set Formulation = mortar
  set Pairs       = block_bottom: substrate_top
  subsection Mortar
    set c_n           = 1e6
    set Jacobian      = approximate
    set Stabilization = velocity update
  end
end
subsection Output
  set Output directory = output_impact_3d
  set VTU interval     = 0
end
subsection Mesh refinement
  set Adapt to contact = true
  set Maximum levels   = 1
  set Passes per step  = 1
  set Lookahead steps  = 3
  set Buffer cells     = 1
end
)",
                       prm);
  std::ostringstream            screen;
  ContactDynamics::Simulator<3> simulator(prm, screen);
  simulator.initialize();
  const auto *contact =
    dynamic_cast<const ContactDynamics::SurfaceContact<3> *>(
      simulator.get_contact());
  unsigned int hanging_primary = 0, most_active = 0;
  double       dt = 0.01;
  while (simulator.current_time() < 0.3 - 1e-12)
    {
      if (!simulator.advance(std::min(dt, 0.3 - simulator.current_time())))
        {
          dt /= 2;
          continue;
        }
      most_active = std::max(most_active, contact->n_active_nodes());
      if (contact->n_active_nodes() > 0)
        hanging_primary =
          std::max(hanging_primary,
                   hanging_surface_nodes(contact->primary_surface(0),
                                         simulator.get_constraints()));
    }
  const auto   stats = read_csv_columns("output_impact_3d/statistics.csv");
  const auto  &cells = stats.at("cells");
  const double E0 =
    stats.at("kinetic_energy").front() + stats.at("elastic_energy").front();
  const double E =
    stats.at("kinetic_energy").back() + stats.at("elastic_energy").back();
  const double transfer = stats.at("transfer_energy").back();
  deallog << "E0 = (1/2) m v0^2 = " << E0 << std::endl;
  check_close("E0 / ((1/2) 7750 kg/m^3 * 1 m^3 * (1 m/s)^2)",
              E0 / 3875,
              1.,
              1e-12);
  check_true("refined during the impact, back to the initial mesh after",
             *std::max_element(cells.begin(), cells.end()) > cells.front() &&
               cells.back() == cells.front());
  check_true("hanging nodes on the primary surface while in contact",
             hanging_primary > 0);
  check_true("the block touched and left",
             most_active > 0 && stats.at("active_contact_nodes").back() == 0);
  check_close("(E - E0 - transfer energy) / E0",
              (E - E0 - transfer) / E0,
              0.,
              1e-9);
  check_close("contact work / E0",
              stats.at("contact_work").back() / E0,
              0.,
              1e-9);
  check_range("energy lost by the coarsening projection / E0",
              -transfer / E0,
              0.,
              0.03);
  check_close("energy balance error / E0",
              stats.at("energy_balance_error").back() / E0,
              0.,
              1e-9);
}
