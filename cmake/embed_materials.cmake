# Writes OUTPUT, a C++ file defining coldspray::materials::builtin_sources(): the text of each
# data/materials/NAME.yaml in INPUTS (paths separated by |), keyed by NAME.
string(REPLACE "|" ";" INPUTS "${INPUTS}")
set(body "// Generated from data/materials/*.yaml by cmake/embed_materials.cmake. Do not edit.\n")
string(APPEND body "#include \"materials/database.hpp\"\n\nnamespace coldspray::materials {\n\n")
string(APPEND body "const std::map<std::string, std::string>& builtin_sources() {\n")
string(APPEND body "  static const std::map<std::string, std::string> sources = {\n")
foreach(input IN LISTS INPUTS)
  get_filename_component(name ${input} NAME_WE)
  file(READ ${input} text)
  string(APPEND body "      {\"${name}\", R\"coldspray(${text})coldspray\"},\n")
endforeach()
string(APPEND body "  };\n  return sources;\n}\n\n}  // namespace coldspray::materials\n")
file(WRITE ${OUTPUT} "${body}")
