# carom's libraries compiled a second time as position-independent code, for the Python module.
#
# A Python extension is a shared object, and code compiled for an executable (-fPIE, Debian's
# default) cannot be linked into one: its thread-local and global data are reached by
# relocations a shared object does not allow. Rather than change how the `carom` binary itself
# is compiled, each library is copied here with the same sources, per-source options, include
# directories, definitions and links, and built with POSITION_INDEPENDENT_CODE. The copies
# follow their originals: a source added to carom_events is in carom_events_pic at the next
# configure.

set(carom_pic_libraries carom_core carom_events carom_fluid carom_scenarios)

# carom_pic_copy(TARGET): defines TARGET_pic from TARGET (a library of carom_pic_libraries).
function(carom_pic_copy target)
  set(copy ${target}_pic)
  get_target_property(sources ${target} SOURCES)
  get_target_property(source_dir ${target} SOURCE_DIR)
  set(paths)
  foreach(source IN LISTS sources)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY "${source_dir}" NORMALIZE OUTPUT_VARIABLE path)
    list(APPEND paths "${path}")
    # Source properties belong to the directory that set them: copy them into this one.
    foreach(property COMPILE_OPTIONS COMPILE_DEFINITIONS SKIP_UNITY_BUILD_INCLUSION UNITY_GROUP)
      get_source_file_property(value "${path}" DIRECTORY "${source_dir}" ${property})
      if(value)
        set_source_files_properties("${path}" PROPERTIES ${property} "${value}")
      endif()
    endforeach()
  endforeach()
  add_library(${copy} STATIC ${paths})
  set_target_properties(${copy} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  foreach(property INCLUDE_DIRECTORIES COMPILE_DEFINITIONS COMPILE_OPTIONS INTERFACE_INCLUDE_DIRECTORIES
                   INTERFACE_COMPILE_DEFINITIONS UNITY_BUILD UNITY_BUILD_BATCH_SIZE)
    get_target_property(value ${target} ${property})
    if(NOT value STREQUAL "value-NOTFOUND")
      set_property(TARGET ${copy} PROPERTY ${property} "${value}")
    endif()
  endforeach()
  # The links of the original, with carom's libraries replaced by their copies.
  set(library_pattern "^(carom_core|carom_events|carom_fluid|carom_scenarios)$")
  get_target_property(libraries ${target} LINK_LIBRARIES)
  get_target_property(interface ${target} INTERFACE_LINK_LIBRARIES)
  foreach(list libraries interface)
    if(NOT ${list})
      set(${list})
    endif()
    list(TRANSFORM ${list} REPLACE "${library_pattern}" "\\1_pic")
  endforeach()
  target_link_libraries(${copy} PRIVATE ${libraries})
  set_property(TARGET ${copy} PROPERTY INTERFACE_LINK_LIBRARIES "${interface}")
endfunction()

foreach(library IN LISTS carom_pic_libraries)
  carom_pic_copy(${library})
endforeach()
