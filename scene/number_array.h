// The numbers of a usd::Value: an immutable array of doubles whose storage every copy of the value
// shares, as USD's copy-on-write VtArray does. Composition copies each authored value into the
// composed layer (a referenced mesh once per instance), and Stage::resolve hands out copies; none
// of them copies the numbers. To change numbers, assign a new array.
//
// It reads like the std::vector<double> it holds (size, [], iteration, ==), and converts to
// `const std::vector<double>&` for code that wants the vector itself.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <vector>

namespace fluence::usd {

class NumberArray {
public:
    using value_type = double;
    using const_iterator = const double*;
    using iterator = const_iterator;

    NumberArray() = default;
    NumberArray(std::vector<double> numbers);  // takes the vector's storage, no copy
    NumberArray(std::initializer_list<double> numbers)
        : NumberArray(std::vector<double>(numbers)) {}

    std::size_t size() const { return numbers_ ? numbers_->size() : 0; }
    bool empty() const { return size() == 0; }
    const double* data() const { return numbers_ ? numbers_->data() : nullptr; }
    const double& operator[](std::size_t i) const { return (*numbers_)[i]; }
    const double& front() const { return numbers_->front(); }
    const double& back() const { return numbers_->back(); }
    const_iterator begin() const { return data(); }
    const_iterator end() const { return data() + size(); }

    const std::vector<double>& vector() const;
    operator const std::vector<double>&() const { return vector(); }

    bool operator==(const NumberArray& other) const { return vector() == other.vector(); }
    bool operator==(const std::vector<double>& other) const { return vector() == other; }

private:
    std::shared_ptr<const std::vector<double>> numbers_;  // null when empty
};

}  // namespace fluence::usd
