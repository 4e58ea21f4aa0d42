// The numbers of a usd::Value: an immutable array of doubles whose storage every copy of the value
// shares, as USD's copy-on-write VtArray does. Composition copies each authored value into the
// composed layer (a referenced mesh once per instance), and Stage::resolve hands out copies; none
// of them copies the numbers. To change numbers, assign a new array.
//
// It reads like the std::vector<double> it holds (size, [], iteration, ==), and converts to
// `const std::vector<double>&` for code that wants the vector itself.
//
// A deferred array (NumberArray::deferred: the crate reader's large arrays) knows its size but
// decodes its numbers on first use: the first access to them (data, [], iteration, vector, ==)
// runs the decoder once, whichever thread asks first (std::call_once; other threads wait), and
// every copy shares the result; the decoder, and whatever it holds (the mapped file), is released
// then. size() and empty() never decode. A decoder that throws leaves the array undecoded: the
// access throws, and the next access tries again.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <memory>
#include <mutex>
#include <vector>

namespace fluence::usd {

class NumberArray {
public:
    using value_type = double;
    using const_iterator = const double*;
    using iterator = const_iterator;
    using Decoder = std::function<std::vector<double>()>;

    NumberArray() = default;
    NumberArray(std::vector<double> numbers);  // takes the vector's storage, no copy
    NumberArray(std::initializer_list<double> numbers) : NumberArray(std::vector<double>(numbers)) {}

    // `size` numbers that `decode` returns when first used (it must return exactly `size`).
    static NumberArray deferred(std::size_t size, Decoder decode);

    std::size_t size() const { return storage_ ? storage_->size : 0; }
    bool empty() const { return size() == 0; }
    const double* data() const { return storage_ ? vector().data() : nullptr; }
    const double& operator[](std::size_t i) const { return vector()[i]; }
    const double& front() const { return vector().front(); }
    const double& back() const { return vector().back(); }
    const_iterator begin() const { return data(); }
    const_iterator end() const { return data() + size(); }

    const std::vector<double>& vector() const {
        static const std::vector<double> kEmpty;
        if (!storage_) return kEmpty;
        if (!storage_->decoded.load(std::memory_order_acquire)) decode();
        return storage_->numbers;
    }
    operator const std::vector<double>&() const { return vector(); }

    // False only for a deferred array whose numbers nothing has read yet.
    bool isDecoded() const { return !storage_ || storage_->decoded.load(std::memory_order_acquire); }

    bool operator==(const NumberArray& other) const { return vector() == other.vector(); }
    bool operator==(const std::vector<double>& other) const { return vector() == other; }

private:
    struct Storage {
        std::size_t size = 0;
        std::vector<double> numbers;
        std::atomic<bool> decoded{false};
        std::once_flag once;
        Decoder decoder;  // null once decoded
    };
    void decode() const;

    std::shared_ptr<Storage> storage_;  // null when empty
};

}  // namespace fluence::usd
