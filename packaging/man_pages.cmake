# Run at build time (`cmake -P`, packaging/CMakeLists.txt passes lancer, help2man and out_dir): writes
# OUT_DIR/lancer.1 and one OUT_DIR/lancer-COMMAND.1 per subcommand that `lancer --help` lists, each made
# by help2man from the built program's own --help, so that a page can never describe options the
# program does not have. help2man (Debian's package) rather than a generator of our own: it already
# turns CLI11's "Options:"/"Camera:" sections and two-column option lists into proper roff, escapes
# what roff would misread, and honours SOURCE_DATE_EPOCH for reproducible packages.
#
# Each page runs the command as `lancer` from PATH, so that its SYNOPSIS says `lancer render`, not the
# build folder's path; a subcommand page is then renamed (title and NAME) to lancer-COMMAND.
cmake_policy(VERSION 3.25)
foreach(variable lancer help2man out_dir)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "man_pages.cmake: -D${variable}=... is required")
  endif()
endforeach()
get_filename_component(lancer_dir "${lancer}" DIRECTORY)
set(ENV{PATH} "${lancer_dir}:$ENV{PATH}")

execute_process(COMMAND "${lancer}" --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "man_pages.cmake: ${lancer} --help failed (${status})")
endif()
execute_process(COMMAND "${lancer}" --version OUTPUT_VARIABLE version_line OUTPUT_STRIP_TRAILING_WHITESPACE)

# The subcommands: the first word of each line of the "Subcommands:" section.
string(REPLACE "\n" ";" lines "${help}")
set(commands "")
set(in_commands FALSE)
foreach(line IN LISTS lines)
  if(line MATCHES "^Subcommands:")
    set(in_commands TRUE)
  elseif(in_commands AND line MATCHES "^  ([a-z][a-z0-9-]*)( |$)")
    list(APPEND commands "${CMAKE_MATCH_1}")
  elseif(in_commands AND NOT line MATCHES "^ ")
    set(in_commands FALSE)
  endif()
endforeach()
if(commands STREQUAL "")
  message(FATAL_ERROR "man_pages.cmake: `lancer --help` lists no subcommands")
endif()

# A page's one-line summary (its NAME section): the first line of its --help, without a trailing period.
function(summary_of help_text out)
  string(REGEX REPLACE "\n.*" "" first "${help_text}")
  string(REGEX REPLACE "^lancer: " "" first "${first}")
  string(REGEX REPLACE "\\.$" "" first "${first}")
  set(${out} "${first}" PARENT_SCOPE)
endfunction()

# SEE ALSO: the other pages, and the manual installed beside them.
function(see_also_for page out)
  set(pages "")
  set(names lancer)
  foreach(command IN LISTS commands)
    list(APPEND names lancer-${command})
  endforeach()
  foreach(other IN LISTS names)
    if(NOT other STREQUAL page)
      list(APPEND pages ".BR ${other} (1)")
    endif()
  endforeach()
  list(JOIN pages ",\n" text)
  set(${out} "${text}\n.PP\nThe full manual: /usr/share/doc/lancer (PREFIX/share/doc/lancer), starting with rendering.md and scene_file.md.\n" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${out_dir}")
file(MAKE_DIRECTORY "${out_dir}")
function(write_page page help_option help_text)
  summary_of("${help_text}" summary)
  string(TOUPPER "${page}" title)
  see_also_for(${page} see_also)
  file(WRITE "${out_dir}/${page}.h2m" "[NAME]\n${page} \\- ${summary}\n[SEE ALSO]\n${see_also}")
  execute_process(COMMAND "${help2man}" --no-info --no-discard-stderr "--help-option=${help_option}"
                          "--version-string=${version_line}" "--include=${out_dir}/${page}.h2m"
                          "--output=${out_dir}/${page}.1" lancer
                  RESULT_VARIABLE status ERROR_VARIABLE errors)
  file(REMOVE "${out_dir}/${page}.h2m")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "man_pages.cmake: help2man failed for ${page}: ${errors}")
  endif()
  # help2man titles every page after the program it ran (LANCER); a subcommand's page is its own.
  file(READ "${out_dir}/${page}.1" roff)
  string(REGEX REPLACE "\n\\.TH LANCER " "\n.TH ${title} " roff "${roff}")
  file(WRITE "${out_dir}/${page}.1" "${roff}")
endfunction()

write_page(lancer "--help" "${help}")
foreach(command IN LISTS commands)
  execute_process(COMMAND "${lancer}" ${command} --help OUTPUT_VARIABLE command_help RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "man_pages.cmake: ${lancer} ${command} --help failed (${status})")
  endif()
  write_page(lancer-${command} "${command} --help" "${command_help}")
endforeach()
