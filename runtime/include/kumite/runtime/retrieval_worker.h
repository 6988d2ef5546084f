#pragma once
// Retrieval off the frame loop (ARCHITECTURE.md step 5): the frame loop posts a request and carries on; a worker
// thread answers it; a later frame picks the answer up. A newer request supersedes an older one the worker has
// not started. The frame loop never waits and never takes a lock: requests and answers pass through lock-free
// triple buffers (latest_value.h), and the worker sleeps on an atomic counter (C++20 wait/notify).

#include "kumite/core/retrieval.h"
#include "kumite/runtime/latest_value.h"

#include <array>
#include <thread>

namespace kumite {

struct RetrievalRequest {
    std::uint64_t ticket = 0; // set by post()
    std::array<float, k_feature_dimensions> pose_feature{};
    HeadingFrame heading;
    Eigen::Vector3d target_world = Eigen::Vector3d::Zero();
    int semantics = -1;
    Side side = Side::none;
    CharacterSize character;

    RetrievalQuery query() const; // a view of this request (its feature stays here)
};

struct RetrievalAnswer {
    std::uint64_t ticket = 0; // the request's
    RetrievalResult result;
    double latency_us = 0.0;  // from post() to the answer's publication
};

class RetrievalWorker {
public:
    explicit RetrievalWorker(const Retriever& retriever);
    ~RetrievalWorker(); // stops and joins the thread
    RetrievalWorker(const RetrievalWorker&) = delete;
    RetrievalWorker& operator=(const RetrievalWorker&) = delete;

    // Frame loop. Fill request() (the ticket is set for you), then post() it; returns the ticket.
    RetrievalRequest& request() { return m_requests.slot(); }
    std::uint64_t post();

    // Frame loop: the newest answer published since the last call, if any.
    const RetrievalAnswer* take_answer() { return m_answers.take() ? &m_answers.current() : nullptr; }

    std::uint64_t answered() const { return m_answered.load(std::memory_order_relaxed); } // queries run so far

private:
    void run();

    const Retriever& m_retriever;
    LatestValue<RetrievalRequest> m_requests;
    LatestValue<RetrievalAnswer> m_answers;
    std::atomic<std::uint64_t> m_posted{0};
    std::atomic<std::uint64_t> m_answered{0};
    std::atomic<bool> m_stop{false};
    std::uint64_t m_next_ticket = 1;
    std::thread m_thread; // last: starts after everything above exists
};

} // namespace kumite
