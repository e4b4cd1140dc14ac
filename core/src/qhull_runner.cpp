// SPDX-License-Identifier: MIT
#include "qhull_runner.h"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include <fmt/format.h>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include "vroc/core/errors.h"

namespace vroc::detail {
namespace {

/// qhull's error stream, captured in memory (open_memstream) so nothing reaches stderr.
class MemoryStream {
public:
    MemoryStream() : file_(open_memstream(&buffer_, &size_)) {}
    ~MemoryStream() {
        if (file_) std::fclose(file_);
        std::free(buffer_);
    }
    MemoryStream(const MemoryStream&) = delete;
    MemoryStream& operator=(const MemoryStream&) = delete;

    FILE* file() const { return file_; }
    /// First non-empty line written so far (qhull puts the error summary there).
    std::string firstLine() {
        if (!file_) return {};
        std::fflush(file_);
        std::string text(buffer_ ? buffer_ : "", size_);
        size_t start = text.find_first_not_of(" \n");
        if (start == std::string::npos) return {};
        size_t end = text.find('\n', start);
        return text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    }

private:
    char* buffer_ = nullptr;
    size_t size_ = 0;
    FILE* file_ = nullptr;
};

/// Owns one qhull instance; frees all qhull memory on scope exit, even after an error.
class QhullInstance {
public:
    explicit QhullInstance(FILE* err) : qh_(std::make_unique<qhT>()) { qh_zero(qh_.get(), err); }
    ~QhullInstance() {
        qh_freeqhull(qh_.get(), !qh_ALL);
        int current_long = 0, total_long = 0;
        qh_memfreeshort(qh_.get(), &current_long, &total_long);
    }
    QhullInstance(const QhullInstance&) = delete;
    QhullInstance& operator=(const QhullInstance&) = delete;
    qhT* get() { return qh_.get(); }

private:
    std::unique_ptr<qhT> qh_;
};

std::vector<QhullFacet> collectFacets(qhT* qh) {
    std::vector<QhullFacet> out;
    facetT* facet;
    vertexT *vertex, **vertexp;
    FORALLfacets {
        QhullFacet f;
        f.outward_normal = Vec3(facet->normal[0], facet->normal[1], facet->normal[2]);
        FOREACHvertex_(facet->vertices) f.point_ids.push_back(qh_pointid(qh, vertex->point));
        out.push_back(std::move(f));
    }
    return out;
}

}  // namespace

std::vector<QhullFacet> runQhull(std::span<const Vec3> points, double merge_distance) {
    std::vector<coordT> coords;
    coords.reserve(points.size() * 3);
    for (const Vec3& p : points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});

    // C-n: pre-merge facets whose centrum is within n of a neighbour (n is raised to qhull's own
    // round-off bound if smaller). No 'Qt': we want merged polygons, not triangles.
    std::string flags = fmt::format("qhull C-{:.6g}", merge_distance);
    MemoryStream err;
    FILE* err_file = err.file();
    if (!err_file) throw GeometryError("convex hull: could not open an in-memory stream for qhull");
    QhullInstance qhull(err_file);
    // qh_new_qhull owns the setjmp: any qhull error longjmps back into it and comes out as a code.
    int code = qh_new_qhull(qhull.get(), 3, static_cast<int>(points.size()), coords.data(), False,
                            flags.data(), nullptr, err_file);
    if (code != 0) {
        std::string why = code == qh_ERRsingular
                              ? "the points are coplanar or collinear (no 3-D volume)"
                              : fmt::format("qhull failed with code {}", code);
        throw GeometryError(fmt::format("convex hull of {} points is degenerate: {} [qhull: {}]",
                                        points.size(), why, err.firstLine()));
    }
    return collectFacets(qhull.get());
}

}  // namespace vroc::detail
