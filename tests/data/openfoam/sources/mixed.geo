// A unit box: a bottom layer of hexahedra (x < 0.5) and prisms (x > 0.5),
// tetrahedra above it, and the pyramids Gmsh puts on the hexahedra's tops.
lc = 0.4;
Point(1) = {0, 0, 0, lc};   Point(2) = {0.5, 0, 0, lc}; Point(3) = {1, 0, 0, lc};
Point(4) = {1, 1, 0, lc};   Point(5) = {0.5, 1, 0, lc}; Point(6) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 5}; Line(3) = {5, 6}; Line(4) = {6, 1};
Line(5) = {2, 3}; Line(6) = {3, 4}; Line(7) = {4, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
Transfinite Curve{1, 2, 3, 4} = 3;
Transfinite Surface{1}; Recombine Surface{1};
a[] = Extrude {0, 0, 0.2} { Surface{1}; Layers{2}; Recombine; };
b[] = Extrude {0, 0, 0.2} { Surface{2}; Layers{2}; Recombine; };
c[] = Extrude {0, 0, 0.8} { Surface{a[0]}; };
d[] = Extrude {0, 0, 0.8} { Surface{b[0]}; };
Physical Surface("bottom") = {1, 2};
Physical Surface("top") = {c[0], d[0]};
Physical Surface("sides") = {a[2], a[4], a[5], b[2], b[3], b[4], c[2], c[4], c[5], d[2], d[3], d[4]};
Physical Volume("fluid") = {a[1], b[1], c[1], d[1]};
