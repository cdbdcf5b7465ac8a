// Compiles the precompiled header (Catch2) that every test program reuses.
