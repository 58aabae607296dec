# shadowproof clip: exact shadow regions of scene files (tests/data/scenes, see its README).
set(CLIP_SCENES ${PROJECT_SOURCE_DIR}/tests/data/scenes)

# [2,4]² at z = 5 under a vertical sun: the shadow is the square itself, area 4, area² 16.
shadowproof_cli_case(NAME "clip: square under a vertical sun, text"
  ARGS clip ${CLIP_SCENES}/square_under_sun.json EXPECT_CODE 0
  STDOUT_REGEX "chart area: 4\n.*area_squared \\(exact square of the 3D area\\): 16\n.*polygons: 1")
shadowproof_cli_case(NAME "clip: square under a vertical sun, json"
  ARGS clip ${CLIP_SCENES}/square_under_sun.json --json EXPECT_CODE 0
  STDOUT_REGEX "\"area_squared\": \"16\".*\"cases\": \\[\\].*\"degenerate\": {.*\"points\": \\[\\].*\"polygons\": \\[.*\"outer\": \\[.*\"2\",.*\"0\"")
# 0.1 read as 1/10: [1/10, 3/10]² → area 1/25, area² 1/625.
shadowproof_cli_case(NAME "clip: decimal JSON numbers are exact"
  ARGS clip ${CLIP_SCENES}/decimal_numbers.json --json EXPECT_CODE 0
  STDOUT_REGEX "\"area_squared\": \"1/625\".*\"area\": \"1/25\"")
# Tetrahedron base (2,2) (6,2) (2,6): area 8 from OFF and from OBJ.
shadowproof_cli_case(NAME "clip: OFF mesh relative to the scene file"
  ARGS clip ${CLIP_SCENES}/tetra_off.json --json EXPECT_CODE 0 STDOUT_REGEX "\"area_squared\": \"64\"")
shadowproof_cli_case(NAME "clip: OBJ mesh relative to the scene file"
  ARGS clip ${CLIP_SCENES}/tetra_obj.json --json EXPECT_CODE 0 STDOUT_REGEX "\"area_squared\": \"64\"")
# Empty shadow is still success.
shadowproof_cli_case(NAME "clip: light parallel to the receiver gives an empty shadow, exit 0"
  ARGS clip ${CLIP_SCENES}/light_parallel.json --json EXPECT_CODE 0
  STDOUT_REGEX "\"area_squared\": \"0\".*\"cases\": \\[[^]]*\"empty\",[^]]*\"light_parallel\"")
# Vertical square in x = 5 under a vertical sun: the segment (5,2,0)–(5,4,0).
shadowproof_cli_case(NAME "clip: edge-on caster reports its segment"
  ARGS clip ${CLIP_SCENES}/edge_on.json --json EXPECT_CODE 0
  STDOUT_REGEX "\"segments\": \\[[ \n]*\\[[ \n]*\\[[ \n]*\"5\",[ \n]*\"2\",[ \n]*\"0\"[ \n]*\\],[ \n]*\\[[ \n]*\"5\",[ \n]*\"4\",[ \n]*\"0\"")
shadowproof_cli_case(NAME "clip: svg picture is written"
  ARGS clip ${PROJECT_SOURCE_DIR}/examples/scenes/demo.json --svg ${CMAKE_CURRENT_BINARY_DIR}/clip_demo.svg
  EXPECT_CODE 0 STDOUT_REGEX "cases: .*caster_edge_on")
shadowproof_cli_case(NAME "clip: float comparison reports the leak"
  ARGS clip ${PROJECT_SOURCE_DIR}/examples/scenes/demo.json --compare-float EXPECT_CODE 0
  STDOUT_REGEX "missing shadow area \\(exact minus float\\): 305/36")

# Malformed scenes: exit 2, a message naming the element, nothing on stdout. (The regexes
# avoid square brackets: CMake keeps a ';' inside unbalanced brackets in the argument list.)
shadowproof_cli_case(NAME "clip: non-planar receiver"
  ARGS clip ${CLIP_SCENES}/nonplanar_receiver.json EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "scene.receiver_not_planar. /receiver/polygon/3 is not in the plane of the receiver")
shadowproof_cli_case(NAME "clip: self-intersecting receiver"
  ARGS clip ${CLIP_SCENES}/self_intersecting_receiver.json EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "scene.self_intersecting. /receiver/polygon is not a simple polygon")
shadowproof_cli_case(NAME "clip: empty caster polygon"
  ARGS clip ${CLIP_SCENES}/empty_polygon.json EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "scene.empty_polygon. /casters/0/polygon: a polygon needs at least 3 vertices, found 0")
shadowproof_cli_case(NAME "clip: bad index in an inline mesh"
  ARGS clip ${CLIP_SCENES}/bad_index_mesh.json EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "scene.bad_index. /casters/0/mesh/faces/1/2: vertex index 3 is not an integer in .0, 3\\)")
shadowproof_cli_case(NAME "clip: bad index in an OFF file"
  ARGS clip ${CLIP_SCENES}/bad_index_off.json EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "scene.bad_index. /casters/0/mesh/file \\('.*bad_index.off'\\) line 6: face 0: vertex index 7 is out of range")
shadowproof_cli_case(NAME "clip: unreadable mesh file"
  ARGS clip ${CLIP_SCENES}/missing_mesh.json EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "scene.mesh_unreadable. /casters/0/mesh/file: cannot open the mesh file '.*no_such_file.off'")
shadowproof_cli_case(NAME "clip: bad number names its path"
  ARGS clip ${CLIP_SCENES}/bad_number.json EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "scene.bad_number. /receiver/polygon/3/2: \"zero\" is not a valid number")
shadowproof_cli_case(NAME "clip: invalid JSON"
  ARGS clip ${CLIP_SCENES}/not_json.json EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "scene.json. the scene is not valid JSON: .*parse error at line 2")
shadowproof_cli_case(NAME "clip: missing scene file"
  ARGS clip ${CLIP_SCENES}/does_not_exist.json EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "scene.unreadable. cannot open the scene file")

# Sun towards (1,1,4): a point moves by −z/4 · (1,1). The square at z = 8 lands on [10,12]²
# (touching the floor at the corner (10,10)); the panel in x = y is edge-on: (3,3,4) → (2,2)
# and (5,5,2) → (9/2,9/2); the triangle (1,6,0) (3,6,0) (2,8,1) → apex (7/4,31/4), area 7/4.
shadowproof_cli_case(NAME "clip: degenerate pieces, points and segments in JSON"
  ARGS clip ${PROJECT_SOURCE_DIR}/examples/scenes/degenerate_pieces.json --json EXPECT_CODE 0
  STDOUT_REGEX "\"area_squared\": \"49/16\".*\"points\": \\[[ \n]*\\[[ \n]*\"10\",[ \n]*\"10\",[ \n]*\"0\"[ \n]*\\][ \n]*\\].*\"segments\": \\[[ \n]*\\[[ \n]*\\[[ \n]*\"2\",[ \n]*\"2\",[ \n]*\"0\"[ \n]*\\],[ \n]*\\[[ \n]*\"9/2\",[ \n]*\"9/2\",[ \n]*\"0\"")

# The light on the receiver's plane: the segment from a receiver point to the light stays in
# the plane, so only the casters' footprint shades (the triangle (1,1) (2,2) (1,3), area 1; the
# points behind it as seen from the light are not shadow).
shadowproof_cli_case(NAME "clip: light on the receiver plane shades the casters' footprint only"
  ARGS clip ${CLIP_SCENES}/light_on_plane_footprint.json EXPECT_CODE 0
  STDOUT_REGEX "cases: light_on_plane caster_in_receiver_plane\n.*area_squared \\(exact square of the 3D area\\): 1\n")
# (1,1) (3,1) (2,1) (2,2): the edges (1,1)-(3,1) and (3,1)-(2,1) overlap.
shadowproof_cli_case(NAME "clip: a caster folding back on itself is not a simple polygon"
  ARGS clip ${CLIP_SCENES}/fold_back.json EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "scene.self_intersecting. /casters/0/polygon is not a simple polygon \\(its edges fold back on each other\\)")
# The cube [1,3]³ as 12 triangles under the sun towards (1,1,2): height h moves by -h/2 (1,1),
# so the shadow is the hull of [-1/2,3/2]² and [1/2,5/2]²: a hexagon of area 8, with both
# builders.
foreach(method silhouette union)
  shadowproof_cli_case(NAME "clip: closed cube mesh casts a hexagon, ${method} builder"
    ARGS clip ${CLIP_SCENES}/closed_cube.json --method ${method} EXPECT_CODE 0
    STDOUT_REGEX "area_squared \\(exact square of the 3D area\\): 64\narea \\(decimal approximation of sqrt\\(area_squared\\)\\): ~8\npolygons: 1\n  polygon 0:\n    outer \\(6 vertices")
endforeach()

# Every JSON field against the text report, on every valid example and test scene.
foreach(scene
    ${PROJECT_SOURCE_DIR}/examples/scenes/demo.json
    ${PROJECT_SOURCE_DIR}/examples/scenes/degenerate_pieces.json
    ${PROJECT_SOURCE_DIR}/examples/scenes/panel_above_light.json
    ${PROJECT_SOURCE_DIR}/examples/scenes/pyramid_on_ramp.json
    ${CLIP_SCENES}/square_under_sun.json ${CLIP_SCENES}/decimal_numbers.json ${CLIP_SCENES}/tetra_off.json
    ${CLIP_SCENES}/light_parallel.json ${CLIP_SCENES}/edge_on.json ${CLIP_SCENES}/light_on_plane_footprint.json
    ${CLIP_SCENES}/closed_cube.json)
  get_filename_component(scene_name ${scene} NAME)
  add_test(NAME "cli: clip --json matches the text report on ${scene_name}"
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:shadowproof_cli> -DSCENE=${scene}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/clip_json_matches_text.cmake)
  set_tests_properties("cli: clip --json matches the text report on ${scene_name}" PROPERTIES LABELS cli)
endforeach()
