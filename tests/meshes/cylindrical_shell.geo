// Quarter of a thick cylindrical shell (radii 1 and 2, height 1) in 27-node
// hexahedra, for tests/gmsh_second_order.cc. Regenerate with
//   gmsh cylindrical_shell.geo -3 -format msh22 -o cylindrical_shell_order2.msh
//   gmsh cylindrical_shell.geo -3 -format msh41 -o cylindrical_shell_order2_v41.msh
SetFactory("Built-in");
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0}; Point(3) = {2, 0, 0};
Point(4) = {0, 2, 0}; Point(5) = {0, 1, 0};
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 3; Transfinite Curve{2, 4} = 4;
Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {0, 0, 1} { Surface{1}; Layers{2}; Recombine; };
Physical Surface("base") = {1}; Physical Surface("top") = {out[0]};
Physical Surface("bottom") = {out[2]}; Physical Surface("outer") = {out[3]};
Physical Surface("left") = {out[4]}; Physical Surface("inner") = {out[5]};
Physical Volume("shell") = {out[1]};
Mesh.ElementOrder = 2;
