// The oblique pull and the braking of tests/friction_sliding_block_3d.cc
// with elements of degree 2 (27-node hexahedra, 9-node contact faces):
// dual mortar with friction (the mortar factors of the dual basis of the
// covered part, tangents of the nodal normals averaged over the curved
// faces) and node-to-segment with friction, with the same bounds as
// degree 1, on the patch-test blocks at Refinement factor 0.5 (4 x 2 x 3
// and 3 x 2 x 2 cells: about the nodes of degree 1's 7 x 4 x 6 and
// 5 x 3 x 4; degree 2 on degree 1's mesh passes too, in 14 minutes).
#include "friction_sliding_block_3d.h"

int
main()
{
  initlog();
  for (const std::string formulation : {"mortar", "nts"})
    {
      pull(formulation, 2);
      braking(formulation, 2);
    }
}
