// The parameters of dual mortar contact (Contact/Mortar).
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/parameters.h>

namespace ContactDynamics
{
  void
  MortarParameters::declare_parameters(ParameterHandler &prm)
  {
    const MortarParameters defaults;
    ComplementarityParameters::declare_parameters(prm,
                                                  defaults.complementarity);
    prm.declare_entry("Segment quadrature points",
                      default_text(defaults.quadrature_points),
                      Patterns::Integer(1, 10),
                      "2-D: Gauss points per mortar segment, in [1, 10]; 2 "
                      "integrates the products of linear functions exactly. "
                      "3-D: the Witherden-Vincent rule on each triangle of "
                      "a clip polygon with this many points per direction, "
                      "in [2, 7] (6, 7, 15, 19, 28, 37 points, exact to "
                      "degree 2n-1; 2 is Dunavant's 6-point rule, exact to "
                      "degree 4, exact for parallelogram faces; on other "
                      "faces the patch test keeps an error of 2e-8 with 2, "
                      "1e-10 with 4, at 2.3 times the cost). 3-D faces of "
                      "degree 2: the rule with one more point per direction "
                      "(at most 7); there the distorted patch test keeps "
                      "1.6e-5 with 2, 1.9e-6 with 4 (with 2 Segment edge "
                      "points; 6.9e-9 with 8).");
    prm.declare_entry(
      "Segment edge points",
      default_text(defaults.segment_edge_points),
      Patterns::Integer(1, 32),
      "3-D faces of degree 2 (9-node faces): points per edge of a primary "
      "face (equally spaced in its coordinates) whose projections onto a "
      "secondary face bound their mortar segment, straight in between in "
      "the secondary face's coordinates; in [1, 32]. Everything else is "
      "integrated on the curved faces. The error this leaves falls with the "
      "fourth power of the points: on the distorted 3-D patch test (with 4 "
      "Segment quadrature points) the pressures are off by 1.9e-6 with 2 "
      "(the face's nodes), 1.1e-7 with 4, 6.9e-9 with 8; exact where the "
      "primary edges project onto straight lines. The cost of the segments "
      "grows about linearly with it.");
  }

  void
  MortarParameters::parse_parameters(ParameterHandler &prm)
  {
    complementarity.parse_parameters(prm);
    quadrature_points   = prm.get_integer("Segment quadrature points");
    segment_edge_points = prm.get_integer("Segment edge points");
  }



} // namespace ContactDynamics
