#!/bin/bash -eu
# ClusterFuzzLite runs the same build as OSS-Fuzz.
exec "$SRC/shadowproof/fuzz/oss-fuzz/build.sh"
