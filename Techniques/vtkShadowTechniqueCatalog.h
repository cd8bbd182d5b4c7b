// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowTechniqueCatalog
 * @brief   The module's shadow techniques by name: their variants, their
 *          parameters, and passes made and set from them.
 *
 * One table every front end reads: the `softshadows` program (technique
 * specs `name[:variant]`, scene parameters in snake_case, the `techniques`
 * listing), the ParaView view (its Shadow Technique choice, and one panel
 * property per parameter) and Python. Techniques, variants and parameters
 * are indices; the first variant of a technique is its default. Parameter
 * values are doubles (0 or 1 for booleans), Vector3 parameters three of
 * them; defaults are not in the table: they are read from a fresh pass
 * (GetParameter()), so they are the classes' own.
 */

#ifndef vtkShadowTechniqueCatalog_h
#define vtkShadowTechniqueCatalog_h

#include "vtkObject.h"
#include "vtkSoftShadowsTechniquesModule.h" // for export macro
#include "vtkWrappingHints.h"               // for VTK_NEWINSTANCE

#include <string> // for std::string

class vtkSoftShadowPass;

class VTKSOFTSHADOWSTECHNIQUES_EXPORT vtkShadowTechniqueCatalog : public vtkObject
{
public:
  static vtkShadowTechniqueCatalog* New();
  vtkTypeMacro(vtkShadowTechniqueCatalog, vtkObject);
  /// Every technique, variant and parameter, with the defaults.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// What a parameter holds.
  enum ParameterTypes
  {
    Boolean = 0,
    Integer,
    Number,
    Vector3 ///< three numbers
  };

  ///@{
  /** Techniques: 0 to GetNumberOfTechniques() - 1; FindTechnique() is -1 for
   * an unknown name. */
  static int GetNumberOfTechniques();
  static int FindTechnique(const char* name);
  static const char* GetTechniqueName(int technique);
  /// One sentence: the class and what it does.
  static const char* GetTechniqueSummary(int technique);
  ///@}

  ///@{
  /** A technique's variants, maybe none; the first is the default. */
  static int GetNumberOfVariants(int technique);
  static int FindVariant(int technique, const char* name);
  static const char* GetVariantName(int technique, int variant);
  static const char* GetVariantMeaning(int technique, int variant);
  ///@}

  ///@{
  /** A technique's parameters, keyed in snake_case as scene files spell
   * them. Minimum and maximum are what SetParameter() accepts, -inf and +inf
   * when unbounded; a Vector3's bound each of its numbers. */
  static int GetNumberOfParameters(int technique);
  static int FindParameter(int technique, const char* key);
  static const char* GetParameterKey(int technique, int parameter);
  static const char* GetParameterMeaning(int technique, int parameter);
  static int GetParameterType(int technique, int parameter);
  /// 3 for a Vector3, else 1.
  static int GetParameterSize(int technique, int parameter);
  static double GetParameterMinimum(int technique, int parameter);
  static double GetParameterMaximum(int technique, int parameter);
  /// Whether every technique has the parameter: one of vtkSoftShadowPass's
  /// own (map_size, the biases, ...), not the technique's.
  static bool IsParameterShared(int technique, int parameter);
  ///@}

  ///@{
  /**
   * A technique SPEC, `name[:variant]` as the `softshadows` program and
   * ParaView's view take it. ParseSpec() puts the technique and the variant
   * (-1 when the SPEC names none: the default) in `ids`; false, saying
   * nothing, when the name is no technique (ids[0] -1) or the variant none
   * of its (ids[1] -1). GetSpecProblem() says what is wrong in one line
   * naming what is known, and is empty for a good SPEC.
   */
  static bool ParseSpec(const char* spec, int ids[2]);
  static std::string GetSpecProblem(const char* spec);
  ///@}

  /**
   * A new pass of `technique` in `variant` (-1 or 0 for the default), every
   * parameter at the class's default; the caller owns it. Null, with an
   * error, for indices out of range.
   */
  VTK_NEWINSTANCE static vtkSoftShadowPass* NewPass(int technique, int variant);

  /// A new pass of a SPEC (ParseSpec()); null, with the SPEC's problem as an
  /// error, for a bad one.
  VTK_NEWINSTANCE static vtkSoftShadowPass* NewPass(const char* spec);

  /**
   * Sets a parameter of `pass`, a pass of `technique`, from
   * GetParameterSize() values. False, with an error naming the technique
   * and key, when the pass is null or of another class or a value is not
   * allowed (IsAllowed()).
   */
  static bool SetParameter(
    vtkSoftShadowPass* pass, int technique, int parameter, const double values[3]);

  /**
   * Whether SetParameter() takes `values` for a parameter: each finite,
   * within the bounds, a whole number for an Integer, 0 or 1 for a Boolean.
   * Says nothing.
   */
  static bool IsAllowed(int technique, int parameter, const double values[3]);

  /// The current value of a parameter of `pass`; false when it has none.
  static bool GetParameter(vtkSoftShadowPass* pass, int technique, int parameter, double values[3]);

protected:
  vtkShadowTechniqueCatalog() = default;
  ~vtkShadowTechniqueCatalog() override = default;

private:
  vtkShadowTechniqueCatalog(const vtkShadowTechniqueCatalog&) = delete;
  void operator=(const vtkShadowTechniqueCatalog&) = delete;
};

#endif
