# The reference samplers (sampling_reference.hpp), shared by tests/sampling and benchmarks/:
# whichever of the two is configured first defines the library.
if(NOT TARGET sweep_sampling_reference)
  add_library(sweep_sampling_reference STATIC ${CMAKE_CURRENT_LIST_DIR}/sampling_reference.cpp)
  target_include_directories(sweep_sampling_reference PUBLIC ${PROJECT_SOURCE_DIR}/tests)
  target_link_libraries(sweep_sampling_reference PUBLIC sweep_io)
  sweep_warnings(sweep_sampling_reference)
endif()
