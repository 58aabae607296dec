# bench_clip compares with Clipper (Debian libpolyclipping-dev), found through pkg-config.
pkg_check_modules(SHADOWPROOF_POLYCLIPPING REQUIRED IMPORTED_TARGET polyclipping)
target_link_libraries(bench_clip PRIVATE PkgConfig::SHADOWPROOF_POLYCLIPPING)
