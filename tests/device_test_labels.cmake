# Read by ctest after the discovered tests (tests/CMakeLists.txt): the device
# tests' labels, and the costs that start the long ones first.
foreach(test IN LISTS device_fast_tests)
  set_tests_properties("${test}" PROPERTIES LABELS "fast;device")
endforeach()
foreach(test IN LISTS device_long_fast_tests)
  set_tests_properties("${test}" PROPERTIES LABELS "fast;device" COST 50)
endforeach()
foreach(test IN LISTS device_slow_tests)
  set_tests_properties("${test}" PROPERTIES LABELS "slow;device" COST 100)
endforeach()
