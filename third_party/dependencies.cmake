# External packages, all from Debian 12 (scripts/setup.sh installs them).
# Only CMake glue lives in third_party/: no outside code is vendored.
#
#   Eigen3 3.4        libeigen3-dev       linear algebra (every layer)
#   MRPT 2.5          libmrpt-dev         EKF baseline, rawlog I/O (eval only)
#   OpenCV 4.6        libopencv-dev       map rendering (eval only)
#   nlohmann_json 3.11 nlohmann-json3-dev scenarios, manifests (eval only)
#   CLI11 2.1         libcli11-dev        command line (eval only)
#   nanoflann 1.4     libnanoflann-dev    k-d tree for scoring (eval only)
#   GTest 1.12        libgtest-dev        tests
#   benchmark 1.7     libbenchmark-dev    benchmarks

find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(CLI11 2.1 REQUIRED)
find_package(nanoflann 1.4 REQUIRED)
find_package(Ceres 2.1 REQUIRED)  # relslam_relax only (issue 19)
find_package(OpenCV 4 REQUIRED COMPONENTS core imgproc imgcodecs videoio)
foreach(module IN ITEMS mrpt-slam mrpt-obs mrpt-io mrpt-serialization mrpt-poses)
  find_package(${module} REQUIRED)
endforeach()

add_library(relslam_mrpt INTERFACE)
target_link_libraries(relslam_mrpt INTERFACE mrpt::slam mrpt::obs mrpt::io mrpt::serialization mrpt::poses)
add_library(relslam_opencv INTERFACE)
target_include_directories(relslam_opencv SYSTEM INTERFACE ${OpenCV_INCLUDE_DIRS})
target_link_libraries(relslam_opencv INTERFACE ${OpenCV_LIBS})

if(RELSLAM_BUILD_TESTS)
  find_package(GTest 1.12 REQUIRED)
endif()
if(RELSLAM_BUILD_BENCHMARKS)
  find_package(benchmark 1.7 REQUIRED)
endif()
