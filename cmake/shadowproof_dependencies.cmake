# Every external library shadowproof uses, found once.
find_package(PkgConfig REQUIRED)
# GMP (rationals, through gmpxx) and MPFR (correct rounding) have no CMake package on Debian.
pkg_check_modules(SHADOWPROOF_GMP REQUIRED IMPORTED_TARGET GLOBAL gmpxx gmp mpfr)
find_package(nlohmann_json 3.10 REQUIRED)
if(SHADOWPROOF_BUILD_CLI)
  find_package(CLI11 2.1 REQUIRED)
endif()
# CGAL 5.5 is header-only; its target brings GMP/MPFR. Only a few src/*.cpp include it.
find_package(CGAL 5.5 REQUIRED)
