# Third-party dependencies, all from Debian packages (see scripts/setup.sh).
find_package(MPI REQUIRED COMPONENTS CXX)
find_package(Trilinos 13.2 REQUIRED COMPONENTS Kokkos Tpetra Belos Ifpack2 Amesos2 Teuchos)
find_package(ExodusII REQUIRED)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)

# Trilinos 13.2 exports plain library names: wrap them in one interface target, with its
# headers as SYSTEM includes so -Wall -Wextra stays about our code.
add_library(argine_deps INTERFACE)
target_include_directories(argine_deps SYSTEM INTERFACE
  ${Trilinos_INCLUDE_DIRS} ${Trilinos_TPL_INCLUDE_DIRS})
target_link_directories(argine_deps INTERFACE ${Trilinos_LIBRARY_DIRS})
target_link_libraries(argine_deps INTERFACE
  ${Trilinos_LIBRARIES} ${Trilinos_TPL_LIBRARIES} ExodusII::ExodusII Eigen3::Eigen MPI::MPI_CXX)

# argine uses MPI's C API only; Open MPI's deprecated C++ bindings do not compile cleanly
# under -Wextra.
target_compile_definitions(argine_deps INTERFACE OMPI_SKIP_MPICXX MPICH_SKIP_MPICXX)

add_library(argine_warnings INTERFACE)
target_compile_options(argine_warnings INTERFACE -Wall -Wextra
  $<$<BOOL:${ARGINE_WERROR}>:-Werror>)
