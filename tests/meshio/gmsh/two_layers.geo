// Two layers side by side (clay | sand) in a 2 m x 1 m box, for the gmsh reader's tests:
// physical surfaces clay and sand, physical curves base (the bottom, two curves) and
// interface (the inner line x = 1, oriented upwards), physical point corner (the origin).
// Made with: gmsh -2 -format msh41 two_layers.geo -o two_layers.msh (add -bin for the binary
// file; -setnumber quads 1 for quadrangles).
DefineConstant[ quads = 0 ];
lc = 0.5;
Point(1) = {0, 0, 0, lc};
Point(2) = {2, 0, 0, lc};
Point(3) = {2, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
Point(5) = {1, 0, 0, lc};
Point(6) = {1, 1, 0, lc};
Line(1) = {1, 5};
Line(2) = {5, 2};
Line(3) = {2, 3};
Line(4) = {3, 6};
Line(5) = {6, 4};
Line(6) = {4, 1};
Line(7) = {5, 6};
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};
If (quads)
  Recombine Surface {1, 2};
EndIf
Physical Surface("clay") = {1};
Physical Surface("sand") = {2};
Physical Curve("base") = {1, 2};
Physical Curve("interface") = {7};
Physical Point("corner") = {1};
