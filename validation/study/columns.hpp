#pragma once
// The names of the result columns that several tools and sections read, each written once here.
// They are the engine's own: tests/validation/study/columns_test.cpp checks every one against the
// engine's column tables (analysis/time_series.cpp: /timeseries, analysis/legs.cpp: /legs), so a
// renamed column fails a test instead of reading nothing. A column only one function reads (the
// energy terms of the energy figure, stage and strain_3 of the critical state's summary) is named
// there, where a rename shows as a missing column in its own test.
#include <array>

namespace validation::col {

// /timeseries
inline constexpr const char* step = "step";
inline constexpr const char* time = "time";
inline constexpr const char* cycle = "cycle";
inline constexpr const char* cycle_end = "cycle_end";
inline constexpr const char* leg_end = "leg_end";
inline constexpr const char* p = "p";
inline constexpr const char* q_over_p = "q_over_p";
inline constexpr const char* stress_11 = "stress_11";
inline constexpr const char* stress_22 = "stress_22";
inline constexpr const char* stress_33 = "stress_33";
inline constexpr const char* stress_12 = "stress_12";
inline constexpr const char* stress_13 = "stress_13";
inline constexpr const char* stress_23 = "stress_23";
inline constexpr const char* void_ratio = "void_ratio";
inline constexpr const char* volumetric_strain = "volumetric_strain";
inline constexpr const char* deviatoric_strain = "deviatoric_strain";
inline constexpr const char* coordination_number = "coordination_number";
inline constexpr const char* coordination_number_mechanical = "coordination_number_mechanical";
inline constexpr const char* pore_pressure_ratio = "pore_pressure_ratio";

inline constexpr std::array series_names = {step, time, cycle, cycle_end, leg_end, p, q_over_p, stress_11, stress_22, stress_33,
                                            stress_12, stress_13, stress_23, void_ratio, volumetric_strain, deviatoric_strain,
                                            coordination_number, coordination_number_mechanical, pore_pressure_ratio};

// /legs (its cycle column is the same name as the series')
inline constexpr const char* target_1 = "target_1";
inline constexpr const char* target_2 = "target_2";
inline constexpr const char* target_3 = "target_3";

inline constexpr std::array legs_names = {cycle, target_1, target_2, target_3};

}  // namespace validation::col
