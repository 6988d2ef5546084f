// The one source of kumite_test_pch, the executable (with no test cases) whose precompiled header every test
// executable reuses (tests/CMakeLists.txt): it only has to exist for CMake to build the header.
