# The proofs compiled against a copy of include/ in which formulas of the library are changed on
# purpose: every changed formula must make its proof fail (tested by check_mutants.cmake).
# Each mutation is: header | text in it (must occur exactly once) | replacement | a step of the
# proofs that must then fail. The copy is refreshed whenever a header changes.
set(SHADOWPROOF_MUTATIONS
  "constructions/shadow.h|return s * identity4<T>() - outer(L.l, P.p)|return s * identity4<T>() + outer(L.l, P.p)|the library's shadow_matrix maps every W as derived"
  "constructions/classify.h|return nearer_than_light ? point_class::shadow : point_class::beyond_light|return nearer_than_light ? point_class::beyond_light : point_class::shadow|of 'point_classes': the facts do not show"
  "constructions/reflect.h|M(i, 3) = T(-2) * P.p[3] * P.p[i] / nn|M(i, 3) = T(2) * P.p[3] * P.p[i] / nn|the library's reflection_matrix"
  "constructions/reflect.h|return translation<T>(-d * N[0], -d * N[1], -d * N[2]) * transpose(R)|return translation<T>(d * N[0], d * N[1], d * N[2]) * transpose(R)|corrected for column vectors"
  "constructions/project.h|M(0, 3) = -(r + l) / (r - l)|M(0, 3) = (r + l) / (r - l)|the library's orthographic, gl"
  "constructions/project.h|H(0, 2) = -cot_theta|H(0, 2) = cot_theta|the library's oblique_shear is H-"
  "constructions/project.h|N(2, 3) = T(2) * n * f / (n - f)|N(2, 3) = T(2) * n * f / (f - n)|the library's perspective_normalization"
  "constructions/project.h|M(0, 2) = (r + l) / (r - l)|M(0, 2) = (r - l) / (r + l)|the library's frustum, d3d"
  "constructions/project.h|M(0, 0) = cot_half_fovy / aspect|M(0, 0) = cot_half_fovy * aspect|the library's perspective, gl"
  "constructions/project.h|T(0), T(0), T(n + f), T(-n * f),|T(0), T(0), T(n - f), T(-n * f),|the library's games101_persp_to_ortho"
  "constructions/normal_matrix.h|return transpose(inverse(M))|return inverse(M)|the library's normal_matrix is"
  "constructions/basis.h|M(i, 3) = -d|M(i, 3) = d|the library's orthonormal shortcut"
  "constructions/basis.h|M(i, 3) = origin[i]|M(i, 3) = -origin[i]|the library's child_to_parent")

set(mutant_root ${CMAKE_CURRENT_BINARY_DIR}/mutant_include)
file(REMOVE_RECURSE ${mutant_root})
file(COPY ${PROJECT_SOURCE_DIR}/include/shadowproof DESTINATION ${mutant_root})
file(GLOB_RECURSE shadowproof_headers ${PROJECT_SOURCE_DIR}/include/shadowproof/*.h ${PROJECT_SOURCE_DIR}/include/shadowproof/*.def)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${shadowproof_headers})
set(SHADOWPROOF_MUTANT_EXPECTED "")
foreach(mutation ${SHADOWPROOF_MUTATIONS})
  string(REPLACE "|" ";" parts "${mutation}")
  list(GET parts 0 header)
  list(GET parts 1 original)
  list(GET parts 2 changed)
  list(GET parts 3 failing_step)
  set(path ${mutant_root}/shadowproof/${header})
  file(READ ${path} text)
  string(FIND "${text}" "${original}" first)
  string(FIND "${text}" "${original}" last REVERSE)
  if(first EQUAL -1 OR NOT first EQUAL last)
    message(FATAL_ERROR "mutants.cmake: '${original}' must occur exactly once in include/shadowproof/${header}; "
                        "update the mutation to the header's current text")
  endif()
  string(REPLACE "${original}" "${changed}" text "${text}")
  file(WRITE ${path} "${text}")
  list(APPEND SHADOWPROOF_MUTANT_EXPECTED "${failing_step}")
endforeach()

# The same derivations and runner, compiled against the changed headers (one unity translation
# unit keeps the extra compile time small).
add_executable(shadowproof_proofs_mutant main.cpp derivations.cpp ${SHADOWPROOF_DERIVATION_SOURCES})
target_include_directories(shadowproof_proofs_mutant BEFORE PRIVATE ${mutant_root})
target_link_libraries(shadowproof_proofs_mutant PRIVATE shadowproof_proof_checker shadowproof_proof_figures)
set_target_properties(shadowproof_proofs_mutant PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
shadowproof_warnings(shadowproof_proofs_mutant)
