#pragma once
// The user's engine code under test: planar shadow matrices in float, as a renderer computes
// them for its shadow pass. Row-major, column vectors: the shadow of V is M V.
namespace engine {

/// M = (P·L) I − L Pᵀ, every entry evaluated in double from the float inputs (each product of
/// two floats is exact in double) and rounded to float once.
void shadow_matrix(const float plane[4], const float light[4], float out[16]);

/// The same with a planted defect, as a refactoring might leave it: entry (3,3) is P·L, the
/// L_w P_d term forgotten. Right whenever the receiver passes through the origin (d = 0), the
/// ground plane of most unit tests; wrong for every other receiver.
void shadow_matrix_with_planted_defect(const float plane[4], const float light[4], float out[16]);

}  // namespace engine
