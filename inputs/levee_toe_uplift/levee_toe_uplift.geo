// The centrifuge levee of thesis Ch. 5 Sec. 4 (toe uplift, test of [18] at N = 120) at
// prototype scale, drawn for gmsh: `gmsh -2 -format msh41 levee_toe_uplift.geo` writes
// levee_toe_uplift.msh, which the decks of this folder read (see README.md).
//
//   y (m)
//    6                    crest 20..24
//                        /----\                (slopes 1:1.5)
//    0  ----------------/      \------------------------  riverside ground 0..11,
//       kaolin cover (3.6 m)                               landside ground 33..50
//  -3.6 ---------------------------------------------------  interface S1
//       sand (2.4 m)
//  -6   ---------------------------------------------------  base (imposed p_L)
//       x = 0          11    20 24  33                 50
//
// Above the ground an empty region ("air", no material, up to y = 7.5 m) gives the moving
// soil elements to move into: the explicit stage's heave and run-out. The soil surface is
// therefore inside the mesh; the decks put their hydraulic conditions on it by zones (the
// current free boundary) and fix the riverside by the node sets of its two curves.
//
// The thesis gives in its text: 50 m long model, clay cover 3.6 m thick on the landside
// (its overburden 73.44 kPa), the base pressure 82 kPa = 2.4 m of water above the ground
// (so the base is 82 / 9.81 - 2.4 = 5.96 m, here 6.0 m, below the ground and the sand 2.4 m
// thick), Tri3 of 0.8 m. The levee's height, crest and slopes (its Fig. 5.31) are choices
// stated in README.md.

h = 0.8;  // element size (m), thesis Sec. 4.2.2

Point(1) = {0, -6, 0, h};     Point(2) = {50, -6, 0, h};
Point(3) = {50, -3.6, 0, h};  Point(4) = {50, 0, 0, h};
Point(5) = {33, 0, 0, h};     Point(6) = {24, 6, 0, h};
Point(7) = {20, 6, 0, h};     Point(8) = {11, 0, 0, h};
Point(9) = {0, 0, 0, h};      Point(10) = {0, -3.6, 0, h};
Point(11) = {50, 7.5, 0, h};  Point(12) = {0, 7.5, 0, h};

Line(1) = {1, 2};    // base
Line(2) = {2, 3};    // landside end, sand
Line(3) = {3, 4};    // landside end, cover
Line(4) = {4, 5};    // landside ground
Line(5) = {5, 6};    // landside slope
Line(6) = {6, 7};    // crest
Line(7) = {7, 8};    // riverside slope
Line(8) = {8, 9};    // riverside ground (reservoir bed)
Line(9) = {9, 10};   // riverside end, cover
Line(10) = {10, 1};  // riverside end, sand
Line(11) = {10, 3};  // interface sand / cover (S1)
Line(12) = {8, 5};   // levee base
Line(13) = {4, 11};  // landside end, air
Line(14) = {11, 12}; // top of the mesh
Line(15) = {12, 9};  // riverside end, air

Curve Loop(1) = {1, 2, -11, 10};
Plane Surface(1) = {1};           // sand
Curve Loop(2) = {11, 3, 4, -12, 8, 9};
Plane Surface(2) = {2};           // cover
Curve Loop(3) = {12, 5, 6, 7};
Plane Surface(3) = {3};           // levee
Curve Loop(4) = {13, 14, 15, -8, -7, -6, -5, -4};
Plane Surface(4) = {4};           // air

Mesh.Algorithm = 6;  // Frontal-Delaunay
Mesh.MeshSizeFromCurvature = 0;

Physical Surface("sand") = {1};
Physical Surface("cover") = {2};
Physical Surface("levee") = {3};
Physical Surface("air") = {4};
Physical Curve("base") = {1};
Physical Curve("river_bed") = {8};         // reservoir bed (fixed, sealed)
Physical Curve("river_slope") = {7};       // riverside slope (fixed, sealed: the membrane)
Physical Curve("landside") = {5, 4};       // landside slope and ground
Physical Curve("crest") = {6};
Physical Curve("river_end") = {10, 9};
Physical Curve("land_end") = {2, 3};
Physical Curve("interface") = {11};
