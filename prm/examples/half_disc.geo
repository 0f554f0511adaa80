// Half of a disc (radius 1, centre at the origin, y <= 0) in quadrilaterals,
// graded towards its lowest point (0, -1), where it touches a plane in
// prm/examples/gmsh_hertz_order2.prm. Regenerate with
//   gmsh half_disc.geo -2 -format msh22 -o half_disc_order2.msh
// and, with straight cells between the same corners,
//   gmsh half_disc.geo -2 -setnumber order 1 -format msh22 -o half_disc_order1.msh
// Mesh.ElementOrder = 2 writes 9-node quadrilaterals whose mid-side nodes
// Gmsh puts on the arc; keep Mesh.SecondOrderIncomplete = 0 (its default:
// 8-node quadrilaterals are not read).
DefineConstant[order = 2];
SetFactory("Built-in");
DefineConstant[fine = 0.02];
coarse = 0.25;
Point(1) = {0, 0, 0, coarse};
Point(2) = {1, 0, 0, coarse};
Point(3) = {0, -1, 0, fine};
Point(4) = {-1, 0, 0, coarse};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 2};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
Physical Curve("arc") = {1, 2}; Physical Curve("top") = {3};
Physical Surface("disc") = {1};
// all quadrilaterals: triangles recombined, then every cell split in four
Mesh.RecombineAll = 1; Mesh.Algorithm = 6; Mesh.SubdivisionAlgorithm = 1;
Mesh.ElementOrder = order;
