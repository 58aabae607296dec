# The proofs compiled against a copy of include/ in which formulas of the library can be changed
# on purpose, one at a time: every changed formula must make its own proof fail, with the other
# formulas intact (tested by check_mutants.cmake). Each mutation is:
#   header | text in it (must occur exactly once) | replacement | derivation | a step of that
#   derivation that must then fail.
# In the copy, the text becomes (shadowproof_mutant_on(k) ? (replacement) : (text)) (a leading
# "return" stays in front), and shadowproof_mutant_on(k) is true only when the environment
# variable SHADOWPROOF_MUTANT is k: the copy with no mutation switched on is the library itself.
# The copy is refreshed whenever a header changes.
set(SHADOWPROOF_MUTATIONS
  "constructions/shadow.h|return s * identity4<T>() - outer(L.l, P.p)|return s * identity4<T>() + outer(L.l, P.p)|shadow_matrix|the library's shadow_matrix maps every W as derived"
  "constructions/classify.h|return nearer_than_light ? point_class::shadow : point_class::beyond_light|return nearer_than_light ? point_class::beyond_light : point_class::shadow|point_classes|of 'point_classes': the facts do not show"
  "constructions/reflect.h|M(i, 3) = T(-2) * P.p[3] * P.p[i] / nn|M(i, 3) = T(2) * P.p[3] * P.p[i] / nn|reflection|the library's reflection_matrix"
  "constructions/reflect.h|return translation<T>(-d * N[0], -d * N[1], -d * N[2]) * transpose(R)|return translation<T>(d * N[0], d * N[1], d * N[2]) * transpose(R)|seed003_reflection_frames|corrected for column vectors"
  "constructions/project.h|M(0, 3) = -(r + l) / (r - l)|M(0, 3) = (r + l) / (r - l)|orthographic|the library's orthographic, gl"
  "constructions/project.h|H(0, 2) = -cot_theta|H(0, 2) = cot_theta|oblique|the library's oblique_shear is H-"
  "constructions/project.h|N(2, 3) = T(2) * n * f / (n - f)|N(2, 3) = T(2) * n * f / (f - n)|perspective_normalisation|the library's perspective_normalization"
  "constructions/project.h|M(0, 2) = (r + l) / (r - l)|M(0, 2) = (r - l) / (r + l)|frustum|the library's frustum, d3d"
  "constructions/project.h|M(0, 0) = cot_half_fovy / aspect|M(0, 0) = cot_half_fovy * aspect|frustum|the library's perspective, gl"
  "constructions/project.h|M(2, 3) = n * f * (z.near_ndc - z.far_ndc) / (f - n)|M(2, 3) = n * f * (z.far_ndc - z.near_ndc) / (f - n)|frustum|the library's frustum, reverse-z"
  "constructions/project.h|M(2, 2) = -z.far_ndc|M(2, 2) = z.far_ndc|frustum|the library's frustum, gl, infinite far plane"
  "constructions/project.h|T(n + f)|T(n - f)|games101_perspective|the library's games101_persp_to_ortho"
  "constructions/normal_matrix.h|return transpose(inverse(M))|return inverse(M)|normal_matrix|the library's normal_matrix is"
  "constructions/basis.h|M(i, 3) = -d|M(i, 3) = d|change_of_basis|the library's orthonormal shortcut"
  "constructions/basis.h|M(i, 3) = origin[i]|M(i, 3) = -origin[i]|change_of_basis|the library's child_to_parent")

set(mutant_root ${CMAKE_CURRENT_BINARY_DIR}/mutant_include)
file(REMOVE_RECURSE ${mutant_root})
file(COPY ${PROJECT_SOURCE_DIR}/include/shadowproof DESTINATION ${mutant_root})
file(GLOB_RECURSE shadowproof_headers ${PROJECT_SOURCE_DIR}/include/shadowproof/*.h ${PROJECT_SOURCE_DIR}/include/shadowproof/*.def)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${shadowproof_headers})
set(mutant_switch [=[
#ifndef SHADOWPROOF_MUTANT_SWITCH
#define SHADOWPROOF_MUTANT_SWITCH
#include <cstdlib>
#include <string>
// True when the environment variable SHADOWPROOF_MUTANT names mutation k of proofs/mutants.cmake.
inline bool shadowproof_mutant_on(int k) {
  const char* chosen = std::getenv("SHADOWPROOF_MUTANT");
  return chosen != nullptr && std::to_string(k) == chosen;
}
#endif
]=])
set(SHADOWPROOF_MUTANT_EXPECTED "")
set(mutated_headers "")
set(index 0)
foreach(mutation ${SHADOWPROOF_MUTATIONS})
  string(REPLACE "|" ";" parts "${mutation}")
  list(GET parts 0 header)
  list(GET parts 1 original)
  list(GET parts 2 changed)
  list(GET parts 3 slug)
  list(GET parts 4 failing_step)
  set(path ${mutant_root}/shadowproof/${header})
  file(READ ${path} text)
  string(FIND "${text}" "${original}" first)
  string(FIND "${text}" "${original}" last REVERSE)
  if(first EQUAL -1 OR NOT first EQUAL last)
    message(FATAL_ERROR "mutants.cmake: '${original}' must occur exactly once in include/shadowproof/${header}; "
                        "update the mutation to the header's current text")
  endif()
  if(original MATCHES "^return (.*)$")
    set(original_value "${CMAKE_MATCH_1}")
    string(REGEX REPLACE "^return " "" changed_value "${changed}")
    set(switched "return shadowproof_mutant_on(${index}) ? (${changed_value}) : (${original_value})")
  else()
    set(switched "(shadowproof_mutant_on(${index}) ? (${changed}) : (${original}))")
  endif()
  string(REPLACE "${original}" "${switched}" text "${text}")
  if(NOT header IN_LIST mutated_headers)
    set(text "${mutant_switch}${text}")
    list(APPEND mutated_headers ${header})
  endif()
  file(WRITE ${path} "${text}")
  list(APPEND SHADOWPROOF_MUTANT_EXPECTED "${index}:${slug}:${failing_step}")
  math(EXPR index "${index} + 1")
endforeach()

# The same derivations and runner, compiled against the changed headers (one unity translation
# unit keeps the extra compile time small).
add_executable(shadowproof_proofs_mutant main.cpp derivations.cpp ${SHADOWPROOF_DERIVATION_SOURCES})
target_include_directories(shadowproof_proofs_mutant BEFORE PRIVATE ${mutant_root})
target_link_libraries(shadowproof_proofs_mutant PRIVATE shadowproof_proof_checker shadowproof_proof_figures)
set_target_properties(shadowproof_proofs_mutant PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
shadowproof_warnings(shadowproof_proofs_mutant)
