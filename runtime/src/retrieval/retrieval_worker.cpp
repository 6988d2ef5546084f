#include "kumite/runtime/retrieval_worker.h"

#include <chrono>

namespace kumite {

RetrievalQuery RetrievalRequest::query() const {
    RetrievalQuery query;
    query.pose_feature = pose_feature;
    query.heading = heading;
    query.target_world = target_world;
    query.semantics = semantics;
    query.side = side;
    query.character = character;
    return query;
}

RetrievalWorker::RetrievalWorker(const Retriever& retriever) : m_retriever(retriever), m_thread([this] { run(); }) {}

RetrievalWorker::~RetrievalWorker() {
    m_stop.store(true, std::memory_order_release);
    m_posted.fetch_add(1, std::memory_order_release);
    m_posted.notify_one();
    m_thread.join();
}

std::uint64_t RetrievalWorker::post() {
    RetrievalRequest& request = m_requests.slot();
    request.ticket = m_next_ticket++;
    const std::uint64_t ticket = request.ticket;
    m_requests.publish();
    m_posted.fetch_add(1, std::memory_order_release);
    m_posted.notify_one();
    return ticket;
}

void RetrievalWorker::run() {
    RetrievalWorkspace workspace = m_retriever.make_workspace();
    std::uint64_t seen = 0;
    while (true) {
        m_posted.wait(seen, std::memory_order_acquire);
        seen = m_posted.load(std::memory_order_acquire);
        if (m_stop.load(std::memory_order_acquire)) return;
        if (!m_requests.take()) continue; // superseded requests were folded into the one already answered
        const RetrievalRequest& request = m_requests.current();
        const auto started = std::chrono::steady_clock::now();
        RetrievalAnswer& answer = m_answers.slot();
        answer.ticket = request.ticket;
        answer.result = m_retriever.query(request.query(), workspace);
        answer.latency_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count();
        m_answers.publish();
        m_answered.fetch_add(1, std::memory_order_relaxed);
    }
}

} // namespace kumite
