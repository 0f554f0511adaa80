// Findings at set-up that do not stop a run but may explain why it stops
// later: a complementarity constant far above E/h, and corners in a dual
// mortar secondary surface. They are printed before the first step and
// repeated in the message of a run that stops for lack of convergence.
#ifndef contact_dynamics_contact_setup_caveats_h
#define contact_dynamics_contact_setup_caveats_h

#include <contact_dynamics/contact/contact_surface.h>

#include <string>
#include <vector>

namespace ContactDynamics
{
  struct ContactParameters;

  /**
   * c_n against the stiffness of the scene, E_max / h (the largest Young's
   * modulus of the scene's bodies over the mean edge of the secondary
   * faces; the
   * weighted gap of unnormalized mortar carries a face measure h^(dim-1)
   * more). Above 1e10 E/h it throws, naming `parameter`: round-off of
   * c_n g then outweighs every contact pressure. Above 1e4 E/h it returns
   * a warning (semi-smooth Newton stalls there, doc/contact.md), else "".
   */
  template <int dim>
  std::string
  complementarity_scale_caveat(
    const ContactParameters                        &contact,
    const std::vector<const ContactSurface<dim> *> &secondary_surfaces,
    const double                                    c_n,
    const bool                                      weighted_gap,
    const std::string                              &parameter);

  /**
   * The sharpest corner of the secondary surfaces of the meshed pairs of a
   * dual mortar formulation: outward normals of faces at one node (of one
   * pair, or of two pairs sharing the node) more than 60 degrees apart.
   * Returns a warning naming the node, the angle and the pairs, or "".
   */
  template <int dim>
  std::string
  secondary_corner_caveat(
    const ContactParameters                        &contact,
    const std::vector<const ContactSurface<dim> *> &secondary_surfaces);
} // namespace ContactDynamics

#endif
