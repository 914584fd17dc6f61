// A piecewise-constant density on the unit square over a grid of non-negative cell weights,
// sampled by inverting a marginal CDF over rows and a conditional CDF within the row. Used to
// importance-sample environment maps.
#pragma once

#include "core/math.h"
#include "sampling/distribution1d.h"

#include <vector>

namespace pt {

class Distribution2D {
public:
    Distribution2D() = default;
    // `weights` holds `rows` rows of `columns` cells, row 0 at v = 0.
    Distribution2D(const std::vector<double>& weights, int columns, int rows) : columns_(columns), rows_(rows) {
        conditional_.reserve(size_t(rows));
        std::vector<double> rowWeights(static_cast<size_t>(rows));
        for (int y = 0; y < rows; ++y) {
            std::vector<double> row(weights.begin() + ptrdiff_t(y) * columns, weights.begin() + ptrdiff_t(y + 1) * columns);
            conditional_.emplace_back(row);
            rowWeights[size_t(y)] = conditional_.back().total();
        }
        marginal_ = Distribution1D(rowWeights);
    }

    // A point of [0, 1)^2 for u in [0, 1)^2, and its density with respect to area on the square.
    Vec2 sample(Vec2 u, float& pdf) const {
        float pRow, pColumn, uRow, uColumn;
        size_t y = marginal_.sample(u.y, &pRow, &uRow);
        size_t x = conditional_[y].sample(u.x, &pColumn, &uColumn);
        pdf = pRow * pColumn * float(columns_) * float(rows_);
        return Vec2((float(x) + uColumn) / float(columns_), (float(y) + uRow) / float(rows_));
    }

    float pdf(Vec2 p) const {
        int x = std::clamp(int(p.x * float(columns_)), 0, columns_ - 1);
        int y = std::clamp(int(p.y * float(rows_)), 0, rows_ - 1);
        return marginal_.pmf(size_t(y)) * conditional_[size_t(y)].pmf(size_t(x)) * float(columns_) * float(rows_);
    }

private:
    int columns_ = 0, rows_ = 0;
    std::vector<Distribution1D> conditional_;
    Distribution1D marginal_;
};

} // namespace pt
