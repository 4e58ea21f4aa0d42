#include "scene/number_array.h"

#include <utility>

namespace fluence::usd {

NumberArray::NumberArray(std::vector<double> numbers) {
    if (!numbers.empty())
        numbers_ = std::make_shared<const std::vector<double>>(std::move(numbers));
}

const std::vector<double>& NumberArray::vector() const {
    static const std::vector<double> kEmpty;
    return numbers_ ? *numbers_ : kEmpty;
}

}  // namespace fluence::usd
