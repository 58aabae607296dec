#!/bin/bash -eu
# OSS-Fuzz / ClusterFuzzLite build script: builds every fuzz/fuzz_<target>.cpp with the
# engine and sanitizers the infrastructure chooses ($CC, $CXX, $CXXFLAGS, $LIB_FUZZING_ENGINE)
# and ships each committed corpus as <target>_seed_corpus.zip.
cd "$SRC/shadowproof"
cmake -S . -B build-oss-fuzz -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_C_COMPILER="$CC" -DCMAKE_CXX_COMPILER="$CXX" -DCMAKE_CXX_FLAGS="$CXXFLAGS" \
  -DSHADOWPROOF_BUILD_FUZZ=ON -DSHADOWPROOF_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" \
  -DSHADOWPROOF_BUILD_TESTS=OFF -DSHADOWPROOF_BUILD_PROOFS=OFF -DSHADOWPROOF_BUILD_CLI=OFF \
  -DSHADOWPROOF_INSTALL=OFF
cmake --build build-oss-fuzz -j"$(nproc)"
for harness in build-oss-fuzz/fuzz/fuzz_*; do
  name=$(basename "$harness")
  cp "$harness" "$OUT/$name"
  corpus="fuzz/corpus/${name#fuzz_}"
  if [ -d "$corpus" ]; then
    (cd "$corpus" && zip -q -r "$OUT/${name}_seed_corpus.zip" .)
  fi
done
