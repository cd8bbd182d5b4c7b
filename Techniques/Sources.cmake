# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# The techniques module's sources (SoftShadows::Techniques): the shadow
# techniques on the framework, and the catalog that makes them by name.
# Shared by the standalone build (CMakeLists.txt here) and the remote-module
# build (cmake/RemoteModule.cmake).
set(softshadows_techniques_classes
  vtkAliasFreeShadowPass
  vtkContactHardeningShadowPass
  vtkHardShadowPass
  vtkOmnidirectionalShadowPass
  vtkReferenceShadowPass
  vtkShadowTechniqueCatalog
  vtkSilhouetteShadowPass
  vtkSmoothieShadowPass)

# A technique's helpers, not installed.
set(softshadows_techniques_private_classes
  vtkAliasFreeBentNormals)
set(softshadows_techniques_private_headers
  vtkShadowSampling.h
  vtkShadowTechniqueCatalogInternals.h)

# Each technique's entry in the catalog: its variants and parameters.
set(softshadows_techniques_catalog_sources
  catalog/aliasfree.cxx
  catalog/contact.cxx
  catalog/hard.cxx
  catalog/omni.cxx
  catalog/reference.cxx
  catalog/silhouette.cxx
  catalog/smoothies.cxx)

# Each technique's shaders, in a folder named as the technique.
set(softshadows_techniques_shaders
  glsl/aliasfree/vtkAliasFreeBendFS.glsl
  glsl/aliasfree/vtkAliasFreeBendVS.glsl
  glsl/aliasfree/vtkAliasFreeCastersFS.glsl
  glsl/aliasfree/vtkAliasFreeCastersGS.glsl
  glsl/aliasfree/vtkAliasFreeCastersVS.glsl
  glsl/aliasfree/vtkAliasFreeListsCS.glsl
  glsl/aliasfree/vtkAliasFreeLookup.glsl
  glsl/aliasfree/vtkAliasFreeLookupBuildCS.glsl
  glsl/contact/vtkContactCoarseFS.glsl
  glsl/contact/vtkContactCommonFS.glsl
  glsl/contact/vtkContactDistanceFS.glsl
  glsl/contact/vtkContactGaussianFS.glsl
  glsl/contact/vtkContactMultiPassFS.glsl
  glsl/contact/vtkContactPCFFS.glsl
  glsl/contact/vtkContactPrepareFS.glsl
  glsl/contact/vtkContactPrepareTexelFS.glsl
  glsl/contact/vtkContactResolveFS.glsl
  glsl/contact/vtkContactTileSpreadFS.glsl
  glsl/contact/vtkContactTilesFS.glsl
  glsl/contact/vtkContactUpsampleFS.glsl
  glsl/omni/vtkOmniPoissonFS.glsl
  glsl/reference/vtkReferenceAccumulateFS.glsl
  glsl/silhouette/vtkSilhouetteBandsGS.glsl
  glsl/silhouette/vtkSilhouetteCommon.glsl
  glsl/silhouette/vtkSilhouetteEdgesFS.glsl
  glsl/silhouette/vtkSilhouetteEdgesVS.glsl
  glsl/silhouette/vtkSilhouetteLookupFS.glsl
  glsl/smoothies/vtkSmoothieEdgesFS.glsl
  glsl/smoothies/vtkSmoothieEdgesGS.glsl
  glsl/smoothies/vtkSmoothieEdgesVS.glsl
  glsl/smoothies/vtkSmoothieLookupFS.glsl
  glsl/smoothies/vtkSmoothieQuadsVS.glsl)
