# Specula as a package: one library of every layer (libspecula, static unless
# SPECULA_SHARED_LIBRARY), its public headers under include/specula/, the command line, the
# shaders, a CMake package (find_package(Specula) → Specula::specula), a pkg-config file, a man
# page; CPack makes Debian packages of it (docs/packaging.md).
# Documents under share/doc/specula, as Debian names the package's directory.
if(NOT CMAKE_INSTALL_DOCDIR)
  set(CMAKE_INSTALL_DOCDIR share/doc/specula)
endif()
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SPECULA_INSTALL_SHADERDIR ${CMAKE_INSTALL_DATADIR}/specula/shaders)
set(SPECULA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/Specula)

# --- The library: the layers' objects in one file, so a user links one thing. -------------
set(SPECULA_LAYERS core settings scene shading gl platform render setup)
set(objects "")
foreach(layer ${SPECULA_LAYERS})
  list(APPEND objects $<TARGET_OBJECTS:specula_${layer}>)
endforeach()
if(SPECULA_SHARED_LIBRARY)
  add_library(specula_library SHARED ${objects})
else()
  add_library(specula_library STATIC ${objects})
endif()
set_target_properties(specula_library PROPERTIES OUTPUT_NAME specula EXPORT_NAME specula LINKER_LANGUAGE CXX
                                                 VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR})
target_compile_features(specula_library INTERFACE cxx_std_20)
# <specula/Specula.h>, and the layer roots its headers include each other by ("core/Error.h").
target_include_directories(specula_library INTERFACE $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
                                                     $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/specula>)
# Public: what the installed headers include. Private: what the objects link (a static
# library's users link them too; SpeculaConfig.cmake finds them).
target_link_libraries(specula_library
  PUBLIC glm::glm fmt::fmt
  PRIVATE spdlog::spdlog OpenEXR::OpenEXR Threads::Threads TinyGLTF::TinyGLTF draco::draco meshoptimizer::meshoptimizer
          PkgConfig::WEBP PkgConfig::PNG PkgConfig::JPEG glfw PkgConfig::EPOXY
          PkgConfig::EGL ${CMAKE_DL_LIBS})

# --- Public headers: what include/specula/Specula.h reaches, found by following includes. ---
# A header from gl/, a private render header or an OpenGL header in that set fails the
# configure: the public API names no GL type.
set(SPECULA_PUBLIC_RENDER_HEADERS Renderer.h View.h PlacedLight.h BakeSettings.h)
function(specula_public_headers out)
  set(todo ${ARGN})
  set(done "")
  while(todo)
    list(POP_FRONT todo header)
    if(header IN_LIST done)
      continue()
    endif()
    list(APPEND done ${header})
    string(REGEX MATCH "^[^/]+" layer "${header}")
    get_filename_component(name "${header}" NAME)
    if(NOT layer MATCHES "^(core|settings|scene|shading|platform|render|setup)$"
       OR (layer STREQUAL "render" AND NOT name IN_LIST SPECULA_PUBLIC_RENDER_HEADERS))
      message(FATAL_ERROR "the public API reaches ${header}, which is not public (a GL or private header)")
    endif()
    file(STRINGS ${CMAKE_SOURCE_DIR}/src/${header} lines REGEX "^[ \t]*#[ \t]*include")
    foreach(line ${lines})
      if(line MATCHES "#[ \t]*include[ \t]+\"([^\"]+)\"")
        list(APPEND todo ${CMAKE_MATCH_1})
      elseif(line MATCHES "#[ \t]*include[ \t]+<(epoxy|GL|EGL|GLFW|glad)/")
        message(FATAL_ERROR "public header ${header} includes an OpenGL header: ${line}")
      endif()
    endforeach()
  endwhile()
  set(${out} ${done} PARENT_SCOPE)
endfunction()
file(STRINGS ${CMAKE_SOURCE_DIR}/include/specula/Specula.h umbrella REGEX "^#include \"[a-z]+/")
string(REGEX REPLACE "#include \"([^\"]+)\"" "\\1" umbrella "${umbrella}")
specula_public_headers(SPECULA_PUBLIC_HEADERS ${umbrella})
# The set follows includes: an edit of the umbrella or of a header in it configures again.
list(TRANSFORM SPECULA_PUBLIC_HEADERS PREPEND ${CMAKE_SOURCE_DIR}/src/ OUTPUT_VARIABLE public_header_paths)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/include/specula/Specula.h ${public_header_paths})
foreach(header ${SPECULA_PUBLIC_HEADERS})
  get_filename_component(dir ${header} DIRECTORY)
  install(FILES src/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/specula/${dir} COMPONENT development)
endforeach()
install(FILES include/specula/Specula.h ${SPECULA_INCLUDE_ROOT}/version/specula/Version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/specula COMPONENT development)

# --- Targets, the CMake package, pkg-config. ------------------------------------------------
install(TARGETS specula RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
install(TARGETS specula_library EXPORT SpeculaTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT development)
# A stripped install (cpack, cmake --install --strip) keeps a static library's symbols and
# drops its debug information (100 MB of 105 in RelWithDebInfo).
if(NOT SPECULA_SHARED_LIBRARY)
  install(CODE "if(CMAKE_INSTALL_DO_STRIP)
    execute_process(COMMAND \"${CMAKE_STRIP}\" --strip-debug
                    \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/$<TARGET_FILE_NAME:specula_library>\")
  endif()" COMPONENT development)
endif()
install(EXPORT SpeculaTargets NAMESPACE Specula:: DESTINATION ${SPECULA_INSTALL_CMAKEDIR} COMPONENT development)
configure_package_config_file(cmake/SpeculaConfig.cmake.in ${CMAKE_BINARY_DIR}/package/SpeculaConfig.cmake
                              INSTALL_DESTINATION ${SPECULA_INSTALL_CMAKEDIR} PATH_VARS SPECULA_INSTALL_SHADERDIR)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/package/SpeculaConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/package/SpeculaConfig.cmake ${CMAKE_BINARY_DIR}/package/SpeculaConfigVersion.cmake
        DESTINATION ${SPECULA_INSTALL_CMAKEDIR} COMPONENT development)

# pkg-config: relocatable (the prefix is found from the .pc file's own place). A static
# libspecula's dependencies go in Requires/Libs, so plain `pkg-config --libs` links.
file(RELATIVE_PATH SPECULA_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" SPECULA_PC_TO_PREFIX "${SPECULA_PC_TO_PREFIX}")
if(SPECULA_SHARED_LIBRARY)
  set(SPECULA_PC_REQUIRES "glm fmt")
  set(SPECULA_PC_REQUIRES_PRIVATE "spdlog OpenEXR tinygltf draco libwebp libpng libjpeg glfw3 epoxy egl")
  set(SPECULA_PC_LIBS_PRIVATE "-lmeshoptimizer -pthread -ldl")
  set(SPECULA_PC_LIBS "")
else()
  set(SPECULA_PC_REQUIRES "glm fmt spdlog OpenEXR tinygltf draco libwebp libpng libjpeg glfw3 epoxy egl")
  set(SPECULA_PC_REQUIRES_PRIVATE "")
  # meshoptimizer installs no pkg-config file.
  set(SPECULA_PC_LIBS "-lmeshoptimizer -pthread -ldl")
  set(SPECULA_PC_LIBS_PRIVATE "")
endif()
configure_file(cmake/specula.pc.in ${CMAKE_BINARY_DIR}/package/specula.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/package/specula.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT development)

# --- Data and documents. ---------------------------------------------------------------------
# The shaders on disk: read before the embedded copy (gl::shaderRoot), to look at and to start
# from with SPECULA_SHADER_DIR. The built-in scenes (demo, learnopengl, doom) are made in code:
# no assets to install.
set(patterns "")
foreach(pattern ${SPECULA_SHADER_PATTERNS})
  list(APPEND patterns PATTERN ${pattern})
endforeach()
install(DIRECTORY shaders/ DESTINATION ${SPECULA_INSTALL_SHADERDIR} COMPONENT runtime FILES_MATCHING ${patterns})
install(FILES docs/specula.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT runtime)
install(FILES README.md docs/api.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
file(GLOB SPECULA_LICENSES ${CMAKE_SOURCE_DIR}/LICENSE* ${CMAKE_SOURCE_DIR}/COPYING*)
if(SPECULA_LICENSES)
  install(FILES ${SPECULA_LICENSES} DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
endif()
# The libraries compiled into the binary (header-only ones, and Debian's static Dear ImGui)
# carry their notices with it.
foreach(package libglm-dev nlohmann-json3-dev libcli11-dev libimgui-dev)
  if(EXISTS /usr/share/doc/${package}/copyright)
    install(FILES /usr/share/doc/${package}/copyright DESTINATION ${CMAKE_INSTALL_DOCDIR}/third-party
            RENAME ${package}.copyright COMPONENT runtime)
  endif()
endforeach()

# --- Debian packages (cpack -G DEB in the build directory; docs/packaging.md). --------------
# specula: the command line, shaders, man page; libspecula-dev: the library, headers, CMake
# package and pkg-config file. Shared-library dependencies come from dpkg-shlibdeps; Mesa's
# EGL and its software rasteriser are what lets `specula render` run on a machine without a GPU.
set(CPACK_PACKAGE_NAME specula)
set(CPACK_PACKAGE_VENDOR "Specula")
set(CPACK_PACKAGE_CONTACT "Specula maintainers <maintainers@users.noreply.h-seed-d9ae19d6.example>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "physically based renderer on OpenGL 4.5, headless or windowed")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime development)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME specula)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "libegl-mesa0, libgl1-mesa-dri")
set(CPACK_DEBIAN_RUNTIME_DESCRIPTION "physically based renderer on OpenGL 4.5, headless or windowed
 Specula renders glTF 2.0 scenes with image-based lighting and post-processing,
 from the command line (headless, on Mesa's llvmpipe when there is no GPU) or in
 a viewer window.")
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME libspecula-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS
    "specula (= ${PROJECT_VERSION}), libglm-dev, libfmt-dev, libspdlog-dev, libopenexr-dev, libtinygltf-dev, libdraco-dev, libmeshoptimizer-dev, libwebp-dev, libpng-dev, libjpeg-dev, libglfw3-dev, libepoxy-dev, libegl-dev, pkg-config")
set(CPACK_DEBIAN_DEVELOPMENT_DESCRIPTION "Specula renderer: static library and headers
 The renderer of the specula command line as a C++20 library: scenes, the
 renderer facade, frame settings, images and errors, with no OpenGL type in its
 headers; find_package(Specula) gives Specula::specula, pkg-config specula.")
include(CPack)
