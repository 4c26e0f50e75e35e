# Third-party libraries, all from Debian 12 packages (scripts/install-deps.sh installs them).
# Facts behind the choices here: shared/reference/dependencies.md.

# Eigen 3.4: geometry for physics.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)

# NLopt 2.7 (C++ build): search strategies. Its config lives under lib/<arch>/cmake/nlopt_cxx; a
# plain find_package(NLopt) would find the C build, which lacks StoGO and AGS.
find_package(
  NLopt 2.7 REQUIRED CONFIG
  PATH_SUFFIXES lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/nlopt_cxx lib/cmake/nlopt_cxx
  NO_CMAKE_PACKAGE_REGISTRY NO_CMAKE_SYSTEM_PACKAGE_REGISTRY)
if(NOT TARGET NLopt::nlopt_cxx)
  message(FATAL_ERROR "found NLopt at ${NLopt_DIR}, but not its C++ build "
                      "(install libnlopt-cxx-dev)")
endif()

# OMPL 1.5: NPC path planning. Its package sets only variables; wrap them in a target whose
# includes are SYSTEM (OMPL's headers warn by the hundred under our flags). OMPL links Boost
# serialization, filesystem and system without its package depending on them: find them here so a
# missing one fails at configure time, not at link time.
find_package(ompl REQUIRED)
find_package(Boost 1.71 REQUIRED COMPONENTS serialization filesystem system)
if(NOT TARGET scenfuzz::ompl)
  add_library(scenfuzz::ompl INTERFACE IMPORTED)
  target_include_directories(scenfuzz::ompl SYSTEM INTERFACE ${OMPL_INCLUDE_DIRS})
  target_link_libraries(
    scenfuzz::ompl INTERFACE ${OMPL_LIBRARIES} Boost::serialization Boost::filesystem
                             Boost::system Eigen3::Eigen)
endif()

# FCL 0.7 and libccd: collision world. libccd's config reports 2.0: do not ask for 2.1.
find_package(fcl 0.6 REQUIRED)
find_package(ccd REQUIRED)

# Protobuf 3.21: Apollo HD maps (physics/map/apollo_map.proto, our own subset of Apollo's schema).
find_package(Protobuf 3.12 REQUIRED)
if(NOT Protobuf_PROTOC_EXECUTABLE)
  message(FATAL_ERROR "protoc not found (install protobuf-compiler)")
endif()

# oneTBB: parallel evaluation.
find_package(TBB REQUIRED)

# Command line and JSON output.
find_package(CLI11 2.1 REQUIRED CONFIG)
find_package(nlohmann_json 3.10 REQUIRED)

# Campaigns (fuzz/campaign/): toml++ 3.3 reads campaign.toml, SQLite 3.40 holds the campaign's
# state. Each is linked PRIVATE to scenfuzz_campaign and included by one facade file only.
# Debian's toml++ ships a CMake config (tomlplusplus::tomlplusplus, a compiled shared library);
# SQLite comes through CMake's own FindSQLite3 module (SQLite::SQLite3).
find_package(tomlplusplus 3 REQUIRED CONFIG)
find_package(SQLite3 3.31 REQUIRED)
# The campaign's JUnit XML: pugixml's CMake config (pugixml::pugixml), linked PRIVATE.
find_package(pugixml 1.11 REQUIRED CONFIG)
# Campaigns spread over several machines under mpirun (fuzz/campaign/mpi_pool.cpp alone).
find_package(MPI 3.1 REQUIRED COMPONENTS CXX)

if(SCENFUZZ_BUILD_TESTS)
  find_package(GTest REQUIRED)
  find_package(benchmark REQUIRED)
endif()
