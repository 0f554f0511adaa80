// A ball of radius 1 in unstructured 27-node hexahedra (tetrahedra split
// in four hexahedra each), and the unit cube meshed the same way, for
// tests/gmsh_second_order.cc:
//   gmsh ball.geo -3 -format msh41 -o ball_order2.msh
//   gmsh ball.geo -3 -setnumber cube 1 -format msh22 -o cube_unstructured_order2.msh
DefineConstant[cube = 0];
SetFactory("OpenCASCADE");
If (cube)
  Box(1) = {0, 0, 0, 1, 1, 1};
  Mesh.MeshSizeMin = 1; Mesh.MeshSizeMax = 1;
Else
  Sphere(1) = {0, 0, 0, 1};
  Mesh.MeshSizeMin = 1; Mesh.MeshSizeMax = 1;
EndIf
Physical Surface("surface") = Surface{:};
Physical Volume("body") = {1};
Mesh.SubdivisionAlgorithm = 2;
Mesh.ElementOrder = 2;
