// The sample mean of independent values with its standard error, for tests whose tolerance
// comes from the estimator's own spread.
#pragma once

#include <algorithm>
#include <cmath>

namespace fluence::test {

class MeanEstimate {
public:
    void add(double v) {
        sum_ += v;
        sumSquares_ += v * v;
        ++count_;
    }
    int count() const { return count_; }
    double mean() const { return sum_ / count_; }
    double standardError() const {
        double m = mean();
        return std::sqrt(std::max(0.0, sumSquares_ / count_ - m * m) / count_);
    }

private:
    double sum_ = 0.0, sumSquares_ = 0.0;
    int count_ = 0;
};

}  // namespace fluence::test
