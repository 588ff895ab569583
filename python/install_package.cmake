# Run by `cmake --install` (python/CMakeLists.txt passes lancer_python, lancer_python_site_dir and
# lancer_package_files): puts the lancer package where the interpreter it was built for looks, under
# the prefix given at install time (`cmake --install build --prefix P`).
#
# Where that is, the interpreter says: of the site directories it would search if it were installed
# at P (site.getsitepackages([P]), those under P/lib), the one it searches now, else the first. On
# Debian's /usr/bin/python3 that is P/lib/python3.11/dist-packages for P = /usr/local (pip's place),
# P/lib/python3/dist-packages for P = /usr (a .deb's) and for any other P (then set PYTHONPATH); in a
# venv, the venv's site-packages; elsewhere P/lib/pythonX.Y/site-packages.
set(query [=[
import os, site, sys
prefix = os.path.normpath(sys.argv[1])
candidates = [d for d in site.getsitepackages([prefix]) if d.startswith(os.path.join(prefix, "lib", ""))]
searched = [d for d in candidates if d in site.getsitepackages()]
print((searched or candidates)[0])
]=])

if(lancer_python_site_dir STREQUAL "")
  execute_process(COMMAND "${lancer_python}" -c "${query}" "${CMAKE_INSTALL_PREFIX}"
                  OUTPUT_VARIABLE site_dir RESULT_VARIABLE status OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT status EQUAL 0 OR site_dir STREQUAL "")
    message(FATAL_ERROR "lancer: ${lancer_python} did not say where packages go under ${CMAKE_INSTALL_PREFIX}; "
                        "configure with -DLANCER_PYTHON_SITE_DIR=lib/python3/dist-packages (or another folder)")
  endif()
elseif(IS_ABSOLUTE "${lancer_python_site_dir}")
  set(site_dir "${lancer_python_site_dir}")
else()
  set(site_dir "${CMAKE_INSTALL_PREFIX}/${lancer_python_site_dir}")
endif()

foreach(file IN LISTS lancer_package_files)
  if(file MATCHES "\\.(py|pyi|typed)$")
    file(INSTALL DESTINATION "${site_dir}/lancer" TYPE FILE FILES "${file}")
  else()
    file(INSTALL DESTINATION "${site_dir}/lancer" TYPE SHARED_LIBRARY FILES "${file}")
  endif()
endforeach()
