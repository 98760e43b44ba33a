#include "core/model/systematic_error_model.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace tt::core {

SystematicErrorModel::SystematicErrorModel(ScaledPolynomial diameterErrorMm, double partLengthMm)
    : m_diameterError(std::move(diameterErrorMm)), m_partLengthMm(partLengthMm) {
    if (!std::isfinite(partLengthMm) || partLengthMm <= 0.0)
        throw std::invalid_argument("the part length must be a positive number of millimetres");
}

}  // namespace tt::core
