// Replaced by the comparison code.
namespace shockgas::compare {}
