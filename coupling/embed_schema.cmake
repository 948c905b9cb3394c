# Writes OUTPUT, a C++ source whose scene_schema_text() returns the text of SCHEMA (docs/scene.schema.json), from
# TEMPLATE. Run by the build (coupling/CMakeLists.txt) whenever the schema changes.
file(READ "${SCHEMA}" SPHSLOPE_SCENE_SCHEMA_TEXT)
configure_file("${TEMPLATE}" "${OUTPUT}" @ONLY)
