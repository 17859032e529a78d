# The WebAssembly build (cmake --preset wasm; web/, docs/web.md). Debian's emscripten brings no
# libraries of its own, so the header-only ones come from Debian's packages: fmt (header-only
# here), CLI11, nlohmann-json and Eigen, through a folder that holds only them. Adding the host's
# /usr/include itself would put the host's C library in front of emscripten's.
set(PARSONS_WASM_INCLUDE ${PROJECT_BINARY_DIR}/wasm-include)
file(MAKE_DIRECTORY ${PARSONS_WASM_INCLUDE})
foreach(pair "fmt=/usr/include/fmt" "CLI=/usr/include/CLI" "nlohmann=/usr/include/nlohmann"
             "Eigen=/usr/include/eigen3/Eigen")
  string(REPLACE "=" ";" parts "${pair}")
  list(GET parts 0 name)
  list(GET parts 1 target)
  if(NOT EXISTS ${target})
    message(FATAL_ERROR "the WebAssembly build needs ${target}: run scripts/install-deps.sh "
                        "(libfmt-dev, libcli11-dev, nlohmann-json3-dev, libeigen3-dev)")
  endif()
  file(CREATE_LINK ${target} ${PARSONS_WASM_INCLUDE}/${name} SYMBOLIC)
endforeach()

foreach(lib CLI11::CLI11 nlohmann_json::nlohmann_json Eigen3::Eigen)
  add_library(${lib} INTERFACE IMPORTED)
  set_target_properties(${lib} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${PARSONS_WASM_INCLUDE})
endforeach()

# parsons reports bad input by exception (DeckError): WebAssembly needs them switched on. Its
# own exception handling (-fwasm-exceptions, in every browser since 2021 and in Node.js 17 on),
# not emscripten's JavaScript emulation, which sends every call that may throw through
# JavaScript and runs the machine several times slower.
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions)

# fmt's implementation compiled once (web/fmt_library.cpp), not header-only in every file
# (after the exception setting above, which a target takes when it is made).
add_library(parsons_wasm_fmt STATIC ${PROJECT_SOURCE_DIR}/web/fmt_library.cpp)
target_include_directories(parsons_wasm_fmt SYSTEM PUBLIC ${PARSONS_WASM_INCLUDE})
add_library(fmt::fmt ALIAS parsons_wasm_fmt)
