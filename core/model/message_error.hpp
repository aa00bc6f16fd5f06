#pragma once
// An error of ours that names no field of the input (InputError does that): a camera or a
// derivation entry the command line refused, a file that cannot be saved. It carries its
// message as data, so the reader sees it in their language
// (core/present/message_text.hpp); what() is its English words.
#include <stdexcept>
#include <utility>

#include "core/model/message.hpp"

namespace ll {

class MessageError : public std::runtime_error {
public:
    explicit MessageError(Message message) : std::runtime_error(message.english()), message_(std::move(message)) {}
    const Message& message() const { return message_; }

private:
    Message message_;
};

}  // namespace ll
