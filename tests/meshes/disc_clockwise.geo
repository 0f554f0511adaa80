// A disc of radius 1 in unstructured 9-node quadrilaterals, every cell
// numbered clockwise (the surface reversed), for tests/gmsh_second_order.cc:
//   gmsh disc_clockwise.geo -2 -format msh22 -o disc_clockwise_order2.msh
SetFactory("Built-in");
lc = 0.4;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {0, 1, 0, lc};
Point(4) = {-1, 0, 0, lc}; Point(5) = {0, -1, 0, lc};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Reverse Surface{1};
Physical Curve("rim") = {1, 2, 3, 4}; Physical Surface("disc") = {1};
Mesh.RecombineAll = 1; Mesh.Algorithm = 6; Mesh.SubdivisionAlgorithm = 1;
Mesh.ElementOrder = 2;
