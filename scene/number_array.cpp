#include "scene/number_array.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace fluence::usd {

NumberArray::NumberArray(std::vector<double> numbers) {
    if (numbers.empty()) return;
    storage_ = std::make_shared<Storage>();
    storage_->size = numbers.size();
    storage_->numbers = std::move(numbers);
    storage_->decoded.store(true, std::memory_order_release);
}

NumberArray NumberArray::deferred(std::size_t size, Decoder decode) {
    NumberArray array;
    if (size == 0) return array;
    array.storage_ = std::make_shared<Storage>();
    array.storage_->size = size;
    array.storage_->decoder = std::move(decode);
    return array;
}

void NumberArray::decode() const {
    Storage& storage = *storage_;
    std::call_once(storage.once, [&storage] {
        std::vector<double> numbers = storage.decoder();
        if (numbers.size() != storage.size)
            throw std::logic_error("a deferred number array decoded " + std::to_string(numbers.size()) +
                                   " numbers instead of " + std::to_string(storage.size));
        storage.numbers = std::move(numbers);
        storage.decoder = nullptr;
        storage.decoded.store(true, std::memory_order_release);
    });
}

}  // namespace fluence::usd
