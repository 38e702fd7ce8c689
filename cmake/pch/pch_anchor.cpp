// The precompiled headers of tests/CMakeLists.txt are made with this (empty) source.
