#pragma once
/// @file PointInitialisation.hpp
/// The initial state of freshly seeded material points from their MaterialSpec (thesis Sec.
/// 2 and 3.2): porosity n0, liquid pressure and density (4.13), S_L and k from the SWRC/HCC
/// at the initial suction (unsaturated), or S_L = 1 and k_sat (saturated), phase masses
/// M_S = (1-n) rho_S V (4.48) and M_L = n S_L rho_L V (4.47), and the initial effective stress
/// sigma'_yy with sigma'_xx = sigma'_zz = K0 sigma'_yy. Dry points carry no liquid (M_L = 0,
/// p_L = 0, S_L = 0). Velocities, displacements and strains start at zero.

#include <vector>

namespace argine {

struct MaterialPoints;
struct MaterialSpec;

/// Initialises every point of `points` (material, volume and positions already seeded).
/// Throws InputError("Materials/<name>/...") for a liquid-carrying material without a
/// positive saturated conductivity or liquid bulk modulus, or a porosity outside (0, 1).
void initialisePointState(const std::vector<MaterialSpec>& materials, MaterialPoints& points);

/// The checks above alone (also done by initialisePointState).
void checkMaterialsForExplicitSolver(const std::vector<MaterialSpec>& materials);

}  // namespace argine
