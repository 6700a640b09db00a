#pragma once
// The checks an Options struct's Check() makes of its fields, with one message form:
// "<Owner>: <field> must be <requirement>, got <value>" (std::invalid_argument).

namespace topay {

/// Throws std::invalid_argument naming the owner (e.g. "NmpcOptions"), the field, what it must
/// be and the value it has.
[[noreturn]] void FailOption(const char* owner, const char* field, double value, const char* requirement);

/// value finite and > 0, else FailOption.
void CheckOptionPositive(const char* owner, const char* field, double value);

/// value finite and >= 0, else FailOption.
void CheckOptionNonNegative(const char* owner, const char* field, double value);

}  // namespace topay
