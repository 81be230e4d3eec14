// A clay levee on a clay cover layer over a sand aquifer (the stratigraphy of thesis Ch. 5
// Sec. 4, toe uplift), drawn for gmsh: `gmsh -2 -format msh41 levee_layered.geo` writes
// levee_layered.msh, which levee_layered.yaml reads (see README.md in this folder).
//
//   y (m)
//    5             crest 25..29
//                 /----\                      (slopes 1:2)
//    0  ---------/      \--------------------  river bed 0..15, landside ground 39..60
//       clay cover (3 m)
//   -3  ----------------------------------------
//       sand aquifer (6 m)
//   -9  ----------------------------------------
//       x = 0          15  25 29  39           60
//
// Elements: 3-node triangles, 1.2 m far from the levee and 0.3 m in a box around the
// landside half of the levee, its toe and the cover beyond it, where the uplift of the cover
// and the slip surface through the landside slope are expected (gmsh Box size field).

fine = 0.3;    // element size in the slip zone (m)
coarse = 1.2;  // element size elsewhere (m)

// Corners
Point(1) = {0, -9, 0};   Point(2) = {60, -9, 0};
Point(3) = {60, -3, 0};  Point(4) = {60, 0, 0};
Point(5) = {39, 0, 0};   Point(6) = {29, 5, 0};
Point(7) = {25, 5, 0};   Point(8) = {15, 0, 0};
Point(9) = {0, 0, 0};    Point(10) = {0, -3, 0};

// Outline and the two inner lines (cover/sand, levee/cover)
Line(1) = {1, 2};    // base
Line(2) = {2, 3};    // far end, sand
Line(3) = {3, 4};    // far end, cover
Line(4) = {4, 5};    // landside ground
Line(5) = {5, 6};    // landside slope
Line(6) = {6, 7};    // crest
Line(7) = {7, 8};    // riverside slope
Line(8) = {8, 9};    // river bed
Line(9) = {9, 10};   // river end, cover
Line(10) = {10, 1};  // river end, sand
Line(11) = {10, 3};  // top of the sand
Line(12) = {8, 5};   // levee base

Curve Loop(1) = {1, 2, -11, 10};
Plane Surface(1) = {1};           // sand
Curve Loop(2) = {11, 3, 4, -12, 8, 9};
Plane Surface(2) = {2};           // cover
Curve Loop(3) = {12, 5, 6, 7};
Plane Surface(3) = {3};           // levee

// Sizes: the Box field, fine inside and growing to coarse over 4 m outside.
Field[1] = Box;
Field[1].XMin = 27; Field[1].XMax = 48;
Field[1].YMin = -4; Field[1].YMax = 5.5;
Field[1].VIn = fine; Field[1].VOut = coarse;
Field[1].Thickness = 4;
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;  // Frontal-Delaunay: well-shaped triangles

Physical Surface("sand") = {1};
Physical Surface("cover") = {2};
Physical Surface("levee") = {3};
Physical Curve("base") = {1};
Physical Curve("river") = {10, 9, 8, 7};     // river end, bed and riverside slope
Physical Curve("landside") = {5, 4};         // landside slope and ground
Physical Curve("far_end") = {2, 3};
Physical Curve("river_end") = {10, 9};
Physical Curve("crest") = {6};
Physical Curve("cover_base") = {11};
