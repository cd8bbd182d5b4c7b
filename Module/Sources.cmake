# The Filters module's classes, shared by the standalone build (CMakeLists.txt
# here) and the remote-module build (cmake/RemoteModule.cmake).
set(softshadows_filters_classes
  vtkFenceSource)
