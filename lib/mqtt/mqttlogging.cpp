// The one logging category of the MQTT wing: connects, losses, refusals, stations heard.
#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcMqtt, "jumo.mqtt", QtInfoMsg)
