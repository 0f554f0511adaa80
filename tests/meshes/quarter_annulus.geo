// Quarter of an annulus (radii 1 and 2) in 9-node quadrilaterals, for
// tests/gmsh_second_order.cc. Regenerate with
//   gmsh quarter_annulus.geo -2 -format msh22 -o quarter_annulus_order2.msh
//   gmsh quarter_annulus.geo -2 -format msh41 -o quarter_annulus_order2_v41.msh
//   gmsh quarter_annulus.geo -2 -setnumber n 2 -format msh22 -o quarter_annulus_order2_fine.msh
//   gmsh quarter_annulus.geo -2 -format msh41 -save_parametric -o quarter_annulus_order2_parametric.msh
DefineConstant[n = 1];
SetFactory("Built-in");
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0}; Point(3) = {2, 0, 0};
Point(4) = {0, 2, 0}; Point(5) = {0, 1, 0};
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 2 * n + 1; Transfinite Curve{2, 4} = 3 * n + 1;
Transfinite Surface{1}; Recombine Surface{1};
Physical Curve("bottom") = {1}; Physical Curve("outer") = {2};
Physical Curve("left") = {3}; Physical Curve("inner") = {4};
Physical Surface("ring") = {1};
Mesh.ElementOrder = 2;
