#pragma once
/// @file TransferScheme.hpp
/// How point velocities and grid momenta are exchanged in the explicit step (stage key
/// `Velocity Transfer`): the thesis' FLIP update, optionally blended with PIC, or APIC.

#include "argine/core/Types.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine {

/// The velocity transfer of a stage, chosen once per stage (the kernels are templates on it).
enum class TransferScheme {
  /// The thesis (7.10, 7.11): v_p += dt sum N a_i; momenta sum N m v_p. Keeps the part of the
  /// point velocities that the grid cannot see (VelocityBlend removes it at a cost).
  Flip,
  /// Affine particle-in-cell (Jiang et al. 2015, J. Comput. Phys. 261): v_p = sum N v~_i and
  /// C_p = sum v~_i (grad N_i)^T from the updated grid velocities v~_i = v_i + dt a_i (with
  /// the velocity conditions); momenta sum N m (v_p + C_p (x_i - x_p)). Conserves linear and
  /// angular momentum in the transfers and leaves no grid-invisible point velocity. For
  /// linear (Tri3, Quad4) shape functions C = sum v~_i (grad N_i)^T is exactly Jiang's
  /// B_p D_p^-1, since there D_p grad N_i = N_i (x_i - x_p).
  Apic,
  /// Taylor PIC in the MUSL step: v_p = sum N v~_i as APIC, the remap without an affine part,
  /// and C_p = the point's velocity gradient of the remapped field (step 4's grad v, per
  /// phase), carried by the next step's momenta. Linear momentum is kept exactly, angular
  /// momentum to the smoothing of the remap; unlike APIC, C_p sees a node's velocity only
  /// through the remap, which weights it by N, so a node that a point barely reaches (N ->
  /// 0 while grad N stays 1/h on linear shapes and at the grid's folded edges) cannot feed
  /// its spurious acceleration back into the point (doc/theory.md Sec. 3.11). After
  /// Nakamura et al. 2023 (Comput. Methods Appl. Mech. Engrg. 404), whose C_p is the grid
  /// velocity gradient at the point.
  Tpic,
  /// Extended PIC of order m (XPIC(m), Hammerquist and Nairn 2017, Comput. Methods Appl.
  /// Mech. Engrg. 318): the FLIP update with the t^k nodal velocities v_i replaced by
  /// v*_i = sum_{k=1..m} (-1)^(k+1) C(m, k) (S S+)^(k-1) v_i, S the mass-weighted P2G of
  /// point velocities, S+ the G2P (XpicFilter.hpp), and then taken in full (a PIC share of 1
  /// per phase): v_p <- S+ (v* + dt a). Of the point velocities this keeps [I - (I - S+ S)^m] v_p:
  /// what the grid cannot see (S v = 0) goes at once, as with PIC, but a resolved mode, which
  /// PIC damps by a factor lambda < 1 of S+ S each step, loses only (1 - lambda)^m: FLIP's low
  /// dissipation without its grid-invisible noise. m - 1 extra G2P/P2G passes a step.
  Xpic,
};

/// The kernels' scheme of a stage's transfer: XPIC is FLIP's update with both PIC shares 1
/// on the filtered nodal velocities (filterNodalVelocitiesXpic before the update).
constexpr TransferScheme kernelScheme(TransferScheme scheme) {
  return scheme == TransferScheme::Xpic ? TransferScheme::Flip : scheme;
}

/// Whether the points of a stage carry an affine velocity matrix C_p (APIC, TPIC).
constexpr bool carriesAffineVelocity(TransferScheme scheme) {
  return scheme == TransferScheme::Apic || scheme == TransferScheme::Tpic;
}

/// The transfer a stage takes when its deck does not name one (`Velocity Transfer: by shape
/// functions`, the default): APIC on the grid families, the scheme for failure stages chosen
/// from the cell-crossing and granular-collapse charts (doc/theory.md, "The scheme for
/// failure stages": FLIP's points never come to rest, TPIC is dissipative); FLIP, the
/// thesis', on linear shapes, where APIC goes unstable at nodes a point barely reaches and
/// TPIC damps the levee slide itself on the scenes' meshes (doc/verification.md, "Mesh
/// convergence of the levee run-out").
constexpr TransferScheme transferForShapes(ShapeFamily shapes) {
  return shapes == ShapeFamily::Linear ? TransferScheme::Flip : TransferScheme::Apic;
}

/// Shares of a PIC update in the FLIP point velocity update, per phase, in [0, 1] and per
/// step; 0 is the thesis' FLIP update (7.10, 7.11). FLIP keeps the part of the point
/// velocities that the grid cannot see (3 points per triangle, 3 nodes): nothing damps it,
/// not even the Darcy drag, which acts on nodal velocities, so it can grow into point-scale
/// noise. A share alpha per step removes that part in about dt / alpha; it also diffuses the
/// resolved velocity (about alpha h^2 / dt), so the solid's share must stay small.
///   solid:  v_S <- v_S + dt sum N a_S,i + alpha_S (sum N v_S,i - v_S)
///   liquid: the relative velocity w = v_L - v_S relaxes towards the grid's, sum N w_i:
///           v_L <- (1 - alpha_L) (v_L + dt sum N a_L,i)
///                  + alpha_L (v_S,new + sum N (w_i + dt (a_L,i - a_S,i)))
/// so the liquid follows the solid's own update and only its Darcy part is taken from the
/// grid: drag-dominated (relaxation time k / (n g)), it has no inertia worth keeping.
///
/// A share per step makes the answer depend on the step: n steps remove (1 - alpha)^n of the
/// grid-invisible velocity, so halving dt at a fixed alpha doubles the damping per second.
/// A rate (1/s, > 0) fixes the damping per second instead: the share of a step of dt is
/// alpha = 1 - exp(-rate dt) (gridShares), per phase, for FLIP (the blends above) and, with
/// APIC's grid velocity and C_p in place of PIC's, for APIC:
///   APIC:   v <- v_APIC + (1 - alpha) (v + dt sum N a_i - v_APIC),  v_APIC = sum N v~_i
/// (the affine FLIP of Fei et al. 2021, ACM Trans. Graph. 40(4), with its FLIP share per
/// second). APIC's own update, v <- v_APIC, loses the velocity beyond the affine field at
/// every transfer; it is the limit rate -> infinity.
struct VelocityBlend {
  Real solid = 0;        ///< alpha_S: PIC share of the solid velocity update (FLIP, per step)
  Real liquid = 0;       ///< alpha_L: grid share of the liquid's relative velocity update
  Real solid_rate = 0;   ///< 1/s; > 0: alpha_S = 1 - exp(-rate dt) each step (FLIP, APIC)
  Real liquid_rate = 0;  ///< 1/s; > 0: alpha_L = 1 - exp(-rate dt) each step (FLIP, APIC)
};

/// alpha_S and alpha_L of a step of dt (VelocityBlend): the grid's shares in the point
/// velocities, PIC's (FLIP, XPIC) or APIC's (APIC, TPIC: 1 unless a rate is set).
VelocityBlend gridShares(TransferScheme scheme, const VelocityBlend& blend, Real dt);

/// XPIC's filter polynomial (XpicFilter.hpp): order m >= 1 (m - 1 PIC round trips a step; 1
/// is PIC) and, for the Chebyshev polynomial, the lower end a in (0, 1) of the eigenvalues of
/// the round trip it keeps (0: the binomial series of Hammerquist and Nairn).
struct XpicPolynomial {
  int order = 2;
  Real lower_eigenvalue = 0;
};

/// What the velocity update and the momentum transfers of a stage need.
/// Per point the shifts of the P2G's forces (`Conjugate Mean Stress`, physics/
/// VolumetricAveraging.hpp): (p, 0) added to the mixture's total sigma_xx and sigma_yy, (p, 1)
/// to p_L in the liquid's force.
using MeanStressShifts = Kokkos::View<Real* [2], MemSpace>;

struct TransferSettings {
  TransferScheme scheme = TransferScheme::Flip;
  VelocityBlend blend;  ///< FLIP only (XPIC: both shares 1)
  /// APIC: the mesh's node coordinates x_i (the momenta carry C_p (x_i - x_p)).
  Kokkos::View<const Real* [kDim], MemSpace> node_coordinates;
  XpicPolynomial xpic{};                 ///< XPIC: its order and polynomial
  MeanStressShifts mean_stress_shift{};  ///< empty: each point's own stress in the forces
};

}  // namespace argine
