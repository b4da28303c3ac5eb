#pragma once
/// \file properties.h
/// What the fuzz targets check about every parser of user text, shared by the libFuzzer
/// targets (fuzz_main.cpp) and by the regression tests of the ordinary suite
/// (tests/test_fuzz_regressions.cpp), so that a regression input is judged exactly as the
/// fuzzer judged it. Each check takes one input and returns what it found wrong, or an
/// empty string when every property holds. A refused input is fine; what is checked is
/// what an accepted input gives.

#include <string>
#include <string_view>

namespace granota::fuzz {

/// core/io/json.h: parse → dump → parse → dump gives the same text (and the pretty form
/// reads back as the same value); every number read is finite.
std::string checkJson(std::string_view input);

/// core/io/point_list.h, all four readers on the same text: what one accepts, written back
/// in each form (inline "x,y;…", CSV, JSON) and read again, is the same list of exact
/// rationals; written as the shortest doubles (as the exports write them) and read
/// again, it is the same list of doubles.
std::string checkPointList(std::string_view input);

/// core/exact/rational.h parseRational: toString of what it reads is in lowest terms and reads
/// back as the same rational; its double reads back as the same double.
std::string checkRational(std::string_view input);

/// core/exact/polynomial_text.h parsePolynomial. The first byte picks the variable ('s' or 'x',
/// anything else 't': the ones Granota writes), the rest is the text: toText of what it reads reads back as
/// the same polynomial and gives the same text again.
std::string checkPolynomial(std::string_view input);

/// core/softbody/scenes/scene.h: a scene (JSON text starting with '{', or the name of a built-in scene)
/// on the first part, then any number of lines "--set key=value" applied in order.
/// Every scene accepted (and after every setting accepted) has only finite numbers,
/// survives sceneToJson → dump → parse → parseScene unchanged, and builds a simulation
/// on both solvers as the Frog tab does; a refused setting leaves the scene unchanged.
std::string checkScene(std::string_view input);

/// Calls the check named by `target` ("json", "point_list", "rational", "polynomial",
/// "scene"); an unknown name is a finding.
std::string checkCore(std::string_view target, std::string_view input);

/// For the fuzz targets: prints the finding and aborts (libFuzzer records the input).
void trapOnFinding(const std::string& finding, std::string_view target);

} // namespace granota::fuzz
