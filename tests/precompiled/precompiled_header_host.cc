// The translation unit CMake builds tests/precompiled's header with; it has no code of its own.
