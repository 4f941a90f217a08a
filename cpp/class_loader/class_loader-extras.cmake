include("${class_loader_DIR}/class_loader_hide_library_symbols.cmake")
