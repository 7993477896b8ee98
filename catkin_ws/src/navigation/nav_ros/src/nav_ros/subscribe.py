"""A publisher's connect callback: what a new subscriber is sent first."""
import rospy


class SendOnSubscribe(rospy.SubscribeListener):
    """Sends `make_message()` to each new subscriber of the topic, unless it returns None: a whole grid before
    its updates, as costmap_2d's connect callback does."""

    def __init__(self, make_message):
        super().__init__()
        self._make_message = make_message

    def peer_subscribe(self, topic_name, topic_publish, peer_publish):
        message = self._make_message()
        if message is not None:
            peer_publish(message)
