# The libraries forcelab-cli needs (readelf's NEEDED entries) include neither
# Qt Widgets nor Qt Charts: it draws with QtGui alone.
#   cmake -DCLI=... -P check_cli_links.cmake
execute_process(COMMAND readelf -d "${CLI}" OUTPUT_VARIABLE dynamic RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "readelf -d ${CLI} failed (exit ${status})")
endif()
if(NOT dynamic MATCHES "libQt6Gui")
  message(FATAL_ERROR "${CLI} does not link QtGui: the check reads the wrong file")
endif()
foreach(library libQt6Widgets libQt6Charts libQt6Concurrent)
  if(dynamic MATCHES "${library}")
    message(FATAL_ERROR "${CLI} links ${library}; the command line needs no more than QtGui")
  endif()
endforeach()
