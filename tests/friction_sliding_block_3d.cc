// 3-D Coulomb friction (mu = 0.3), dual mortar, on the non-matching,
// distorted meshes of the 3-D patch-test scene, pulled and sliding along
// the oblique direction d = (cos 30°, 0, sin 30°), which no mesh line
// follows: the friction law is a vector law (slip along the trial traction),
// so the friction force must be mu N and point along the sliding, not along
// a mesh or tangent direction. The upper block is shifted by (0.01, 0,
// 0.013): where the boundary edges of the two surfaces coincide and stick,
// the clipped areas are not differentiable and Newton stalls at 1e-8 of the
// force (doc/contact.md, "3-D friction"). What is asserted, against what:
// 1. Quasi-static: the upper block (nu = 0, E = 1e6) is pressed onto the
//    lower one by 1e-3 and then its top is pulled along d by
//    u(t) = 1e-3 (t - 1), up to 2e-3 (the 2-D test friction_sliding_block
//    along x):
//    - at a small tangential force (T < mu N / 2) no node slips;
//    - in gross sliding (t >= 2.5) every node slips, and the reaction on
//      the lower block's support (from the bulk residual, not from the
//      contact forces) has |R_t| / R_y = mu within 2 % and R_t along d
//      within 1 degree;
//    - the frictional dissipation over the gross sliding is the friction
//      force times the slip distance: D(3) - D(2.5) = mu int R_y du_top
//      within 2 %;
//    - the energy balance with the frictional dissipation closes.
// 2. Dynamics: the upper block (rho = 1, g = 10) slides with the initial
//    velocity 0.5 d and is braked by friction for 0.1 s: its mean
//    deceleration is mu g (within 3 %) and opposite to d (within 1 degree:
//    an isotropic friction law); the energy balance closes to 1 % of the
//    dissipation (0.48 % measured: jumps at the steps where nodes come back
//    into contact while sliding; 0.33 % at half the step).
// The same for node-to-segment (nodal forces along the tangents of the
// primary normal at the closest point): the same bounds, except that the
// pull's energy balance closes only to 1 % of the dissipation (measured
// -0.47 %: the work of the normal forces as the nodes slide over the
// primary surface that their uneven loads bend; mortar 3e-7).
// The measured values are in the file "measured" beside "output".
#include "friction_sliding_block_3d.h"

int
main()
{
  initlog();
  for (const std::string formulation : {"mortar", "nts"})
    {
      pull(formulation, 1);
      braking(formulation, 1);
    }
}
